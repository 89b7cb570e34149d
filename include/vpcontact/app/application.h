// The command line of the program: run a scene, print the parameters, help.
#ifndef vpcontact_application_h
#define vpcontact_application_h

namespace VPContact
{
  /**
   * Run the program as `vpcontact [--help | --print-parameters [dim] |
   * [--resume] scene.prm]`: initialize MPI, read the dimension from the
   * scene (which rank 0 reads for all ranks), run the simulator of that
   * dimension. Errors are caught here and printed as one clean message,
   * by rank 0 or, if one rank stopped alone, by that rank (see
   * ExitAgreement); the return value is the exit status: 0, 1 on an error,
   * 75 when a signal stopped the run after a checkpoint.
   */
  int
  run_application(int argc, char **argv);
} // namespace VPContact

/// run_application() under a name without C++ mangling, for the executable,
/// which loads the library with dlopen() (main.cc).
extern "C" int
vpcontact_run_application(int argc, char **argv);

#endif
