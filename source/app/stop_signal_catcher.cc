// The signals that stop a run at the end of a step, with a checkpoint (see
// stop_signal_catcher.h and doc/checkpoint.md).
#include <vpcontact/app/stop_signal_catcher.h>

namespace VPContact
{
  namespace
  {
    // The one piece of global state a signal handler may touch: the number
    // of the first signal that arrived (an async-signal-safe store).
    volatile std::sig_atomic_t stop_signal = 0;
    // Whether a SIGPIPE came, whatever came first.
    volatile std::sig_atomic_t pipe_broken = 0;

    void
    record_stop_signal(const int signal)
    {
      if (signal == SIGPIPE)
        pipe_broken = 1;
      if (stop_signal == 0)
        stop_signal = signal;
    }
  } // namespace



  StopSignalCatcher::StopSignalCatcher()
  {
    stop_signal = 0;
    pipe_broken = 0;
    for (unsigned int i = 0; i < signals.size(); ++i)
      {
        sigaction(signals[i], nullptr, &previous[i]);
        if (previous[i].sa_handler == SIG_IGN)
          continue;
        struct sigaction action = {};
        action.sa_handler       = record_stop_signal;
        sigemptyset(&action.sa_mask);
        // SA_RESTART: a system call that the signal interrupts (MPI, file
        // output) continues; SA_RESETHAND: the next signal acts as usual,
        // except SIGPIPE, which every later write to the broken pipe
        // raises again.
        action.sa_flags = SA_RESTART;
        if (signals[i] != SIGPIPE)
          action.sa_flags |= SA_RESETHAND;
        installed[i] = (sigaction(signals[i], &action, nullptr) == 0);
      }
  }



  StopSignalCatcher::~StopSignalCatcher()
  {
    for (unsigned int i = 0; i < signals.size(); ++i)
      if (installed[i])
        {
          if (signals[i] == SIGPIPE && pipe_broken)
            {
              // The screen output is gone for good: what is still written
              // to it (the end of the run) must not end the program.
              struct sigaction ignore = {};
              ignore.sa_handler       = SIG_IGN;
              sigemptyset(&ignore.sa_mask);
              sigaction(SIGPIPE, &ignore, nullptr);
            }
          else
            sigaction(signals[i], &previous[i], nullptr);
        }
    stop_signal = 0;
  }



  int
  StopSignalCatcher::caught_signal()
  {
    return stop_signal;
  }



  bool
  StopSignalCatcher::output_pipe_broken()
  {
    return pipe_broken != 0;
  }



  std::string
  StopSignalCatcher::name(const int signal)
  {
    switch (signal)
      {
        case SIGINT:
          return "SIGINT";
        case SIGTERM:
          return "SIGTERM";
        case SIGUSR1:
          return "SIGUSR1";
        case SIGPIPE:
          return "SIGPIPE";
        default:
          return "signal " + std::to_string(signal);
      }
  }
} // namespace VPContact
