// The vpcontact executable: everything happens in run_application().
#include <vpcontact/application.h>

int
main(int argc, char **argv)
{
  return VPContact::run_application(argc, argv);
}
