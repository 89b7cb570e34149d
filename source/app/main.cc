// The vpcontact executable: everything happens in run_application(), after
// the process has restarted itself with huge pages for its heap where the
// kernel gives them only on request (huge_pages.h).
#include <vpcontact/app/application.h>
#include <vpcontact/app/huge_pages.h>

int
main(int argc, char **argv)
{
  VPContact::restart_with_huge_pages(argv);
  return VPContact::run_application(argc, argv);
}
