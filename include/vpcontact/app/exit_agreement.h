// How the ranks end the program together: whether any of them stopped with
// an error, whose message the user reads, and what a rank that stopped alone
// does while the others wait for it.
#ifndef vpcontact_exit_agreement_h
#define vpcontact_exit_agreement_h

#include <functional>
#include <mpi.h>
#include <string>

namespace VPContact
{
  /**
   * The last collective step of the program. Every input error and almost
   * every run-time failure is found by all ranks alike (from the same
   * input, or after a reduction), and all of them then stop here together:
   * rank 0 prints one message, and every rank exits with status 1.
   *
   * An error that one rank meets alone (a file only it reads, a check of
   * only its cells) leaves the others waiting for it in the next
   * collective call of the computation, which they never leave. So a rank
   * with an error waits here only a while for the others: if they do not
   * come, it prints its own message, naming its rank, and ends all ranks
   * with MPI_Abort, the only way left to free them.
   *
   * The agreement runs on a duplicate of the communicator, made when the
   * object is built (before anything can fail on one rank only), so that
   * it never meets a collective call of the computation.
   */
  class ExitAgreement
  {
  public:
    /// Collective.
    explicit ExitAgreement(const MPI_Comm communicator);

    ~ExitAgreement();

    ExitAgreement(const ExitAgreement &) = delete;
    ExitAgreement &
    operator=(const ExitAgreement &)
      = delete;

    /**
     * The exit status of the program: @p status if no rank has an error,
     * else 1. @p error is this rank's error message, empty if it has none.
     * Rank 0 prints the message of the first rank that has one.
     */
    int
    finish(const int status, const std::string &error) const;

    /// How long a rank with an error waits for the others, in seconds.
    static constexpr double wait_for_others = 10;

  private:
    MPI_Comm communicator;
  };

  /**
   * Run @p task, which may throw on some ranks and not on others (a check
   * at the quadrature points of a rank's own cells), and then throw on
   * every rank of @p communicator the message of the first rank whose task
   * threw: all ranks stop together instead of the others waiting for it in
   * the next collective call. Collective; a task that threw nowhere costs
   * one reduction of a flag.
   */
  void
  stop_together(const MPI_Comm communicator, const std::function<void()> &task);
} // namespace VPContact

#endif
