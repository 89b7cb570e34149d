// The signals that stop a run at the end of a step, with a checkpoint:
// SIGINT, SIGTERM, SIGUSR1, and SIGPIPE when the reader of the screen output
// has gone.
#ifndef vpcontact_stop_signal_catcher_h
#define vpcontact_stop_signal_catcher_h

#include <array>
#include <csignal>
#include <string>

namespace VPContact
{
  /**
   * The exit status of a run that stopped on a signal after writing a
   * checkpoint: 75, EX_TEMPFAIL of sysexits.h ("temporary failure; the user
   * is invited to retry"), so that a job script can tell "resume me" from
   * success (0) and from an error (1).
   */
  constexpr int exit_status_stopped_for_resume = 75;

  /**
   * While an object of this class exists, SIGINT, SIGTERM, SIGUSR1 and
   * SIGPIPE do not end the program: they only record that a stop was asked
   * for, and the time loop stops cleanly at the end of the current step,
   * after writing a checkpoint. A second SIGINT, SIGTERM or SIGUSR1 ends the
   * program at once (the handler is reset to the default after the first
   * one), so that a user who presses Ctrl-C twice is not kept waiting. A
   * signal that was ignored when the object was made (nohup) stays ignored.
   * The destructor restores the previous handlers and forgets the signal.
   *
   * SIGPIPE comes with a write to a pipe whose reader has gone
   * (`vpcontact scene.prm | head -3`): the screen output is lost from then
   * on, the state is not. Its handler stays in place, so that the further
   * writes of the step and of the checkpoint fail quietly (EPIPE) instead
   * of ending the program; after a SIGPIPE the destructor leaves SIGPIPE
   * ignored, since the pipe stays broken for the rest of the process.
   */
  class StopSignalCatcher
  {
  public:
    StopSignalCatcher();
    ~StopSignalCatcher();
    StopSignalCatcher(const StopSignalCatcher &) = delete;
    StopSignalCatcher &
    operator=(const StopSignalCatcher &)
      = delete;

    /// The first signal that arrived on this rank, or 0.
    static int
    caught_signal();

    /**
     * Whether a SIGPIPE arrived while an object of this class existed: the
     * screen output (a pipe) has lost its reader, and what is still to be
     * said goes to the error output.
     */
    static bool
    output_pipe_broken();

    /// "SIGTERM" and so on.
    static std::string
    name(const int signal);

  private:
    static constexpr std::array<int, 4> signals
      = {{SIGINT, SIGTERM, SIGUSR1, SIGPIPE}};
    std::array<struct sigaction, 4> previous;
    std::array<bool, 4>             installed = {{false, false, false, false}};
  };
} // namespace VPContact

#endif
