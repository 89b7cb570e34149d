// The vpcontact executable: everything happens in run_application().
#include <vpcontact/app/application.h>

int
main(int argc, char **argv)
{
  return VPContact::run_application(argc, argv);
}
