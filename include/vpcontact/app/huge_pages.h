// Transparent huge pages for the heap, on request (VPCONTACT_HUGE_PAGES=1):
// on kernels that give them only to memory that asks for them, the program
// starts itself again with glibc's malloc told to ask.
#ifndef vpcontact_huge_pages_h
#define vpcontact_huge_pages_h

#include <string>

namespace VPContact
{
  /**
   * The value GLIBC_TUNABLES needs for glibc's malloc to ask for
   * transparent huge pages (madvise(MADV_HUGEPAGE) on the memory it maps),
   * or "" where no restart is asked for or it would change nothing:
   * - @p request (VPCONTACT_HUGE_PAGES, nullptr if unset) is not "1";
   * - @p thp_enabled, the text of /sys/kernel/mm/transparent_hugepage/enabled,
   *   does not select "[madvise]" (with "[always]" every large mapping gets
   *   huge pages already, with "[never]" none can);
   * - @p glibc_version (gnu_get_libc_version()) is older than 2.35, which
   *   has no such tunable;
   * - @p tunables (the present GLIBC_TUNABLES, nullptr if unset) sets
   *   glibc.malloc.hugetlb already, to any value: the user's choice stands.
   */
  std::string
  huge_page_tunables(const std::string &thp_enabled,
                     const std::string &glibc_version,
                     const char        *tunables,
                     const char        *request);

  /**
   * Start this executable again (execv of /proc/self/exe with the same
   * arguments) with huge_page_tunables() in its environment, where that is
   * not empty. Called first in main(), before MPI starts, so that under
   * mpirun each rank does it alone. Returns where it does not restart, or
   * where the restart fails (the run then goes on with 4 KiB pages).
   */
  void
  restart_with_huge_pages(char **argv);
} // namespace VPContact

#endif
