// The ranks' agreement at the end of the program on its exit status and its
// error message.
#include <vpcontact/app/exit_agreement.h>
#include <vpcontact/input/input_error.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <chrono>
#include <iostream>
#include <thread>
#include <vector>

namespace VPContact
{
  namespace
  {
    // Whether @p request completes within @p seconds.
    bool
    completes_within(MPI_Request &request, const double seconds)
    {
      const auto end = std::chrono::steady_clock::now()
                       + std::chrono::duration<double>(seconds);
      for (;;)
        {
          int done = 0;
          MPI_Test(&request, &done, MPI_STATUS_IGNORE);
          if (done)
            return true;
          if (std::chrono::steady_clock::now() >= end)
            return false;
          std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }

    void
    print_error(const std::string &message, const std::string &where)
    {
      std::cerr << "\nError" << where << ": " << message
                << "\nStopped; exit status 1." << std::endl;
    }
  } // namespace



  ExitAgreement::ExitAgreement(const MPI_Comm world)
  {
    MPI_Comm_dup(world, &communicator);
  }



  ExitAgreement::~ExitAgreement()
  {
    MPI_Comm_free(&communicator);
  }



  int
  ExitAgreement::finish(const int status, const std::string &error) const
  {
    const unsigned int rank
      = dealii::Utilities::MPI::this_mpi_process(communicator);
    const int   failed     = error.empty() ? 0 : 1;
    int         any_failed = 0;
    MPI_Request request;
    MPI_Iallreduce(&failed,
                   &any_failed,
                   1,
                   MPI_INT,
                   MPI_MAX,
                   communicator,
                   &request);
    // A rank without an error waits as long as it takes: a rank with one
    // either comes or ends the program.
    if (failed == 0)
      MPI_Wait(&request, MPI_STATUS_IGNORE);
    else if (!completes_within(request, wait_for_others))
      {
        print_error(
          error,
          " on MPI rank " + std::to_string(rank) + " of "
            + std::to_string(
              dealii::Utilities::MPI::n_mpi_processes(communicator))
            + " (the other ranks did not stop with it; all are ended)");
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    if (any_failed == 0)
      return status;

    const std::vector<std::string> messages
      = dealii::Utilities::MPI::gather(communicator, error, 0);
    if (rank == 0)
      for (unsigned int r = 0; r < messages.size(); ++r)
        if (!messages[r].empty())
          {
            print_error(messages[r],
                        r == 0 ? "" : " on MPI rank " + std::to_string(r));
            break;
          }
    return 1;
  }



  void
  stop_together(const MPI_Comm communicator, const std::function<void()> &task)
  {
    std::string problem;
    try
      {
        task();
      }
    catch (const std::exception &e)
      {
        problem = error_message(e);
        if (problem.empty())
          problem = "a check failed without a message.";
      }
    if (!dealii::Utilities::MPI::logical_or(!problem.empty(), communicator))
      return;
    for (const auto &message :
         dealii::Utilities::MPI::all_gather(communicator, problem))
      AssertThrow(message.empty(), dealii::ExcMessage(message));
  }
} // namespace VPContact
