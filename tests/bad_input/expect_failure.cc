// Test driver for input errors: runs the program on the given arguments and
// turns "stopped with an error" into success, so that the test can compare
// the error message. A scene that runs to the end is a test failure.
#include <vpcontact/application.h>

#include <iostream>

int
main(int argc, char **argv)
{
  const int status = VPContact::run_application(argc, argv);
  // Only the exit status is printed here; the message went to stderr, which
  // the test harness records together with stdout.
  std::cerr << "[expect_failure] exit status "
            << (status == 0 ? "0: the program did NOT stop" : "non-zero")
            << std::endl;
  return status == 0 ? 1 : 0;
}
