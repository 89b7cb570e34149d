// Transparent huge pages for the heap, on request: where the kernel gives
// them only to memory that asks for them and VPCONTACT_HUGE_PAGES=1 is set,
// the program starts itself again with glibc's malloc told to ask.
//
// Why it is a choice and not the default: a run allocates large arrays
// again and again (the factors of every factorization, the vectors of a new
// mesh, the estimate's buffers, the patches and the text of every field
// file), and with 4 KiB pages the kernel maps each page on its first touch,
// in a page fault. With 2 MiB pages there are up to 512 times fewer faults,
// and the factors' substitutions miss the TLB less. But each huge page must
// be found whole and cleared at its first touch, and on the virtual
// machines measured (Intel Xeon and AMD EPYC, scripts/bench --huge-pages)
// that cost about as much as the fewer faults saved over a run, or more
// (doc/performance.md). Most distributions
// set transparent huge pages to "madvise": only memory marked with
// madvise(MADV_HUGEPAGE) gets them, and glibc's malloc marks its memory
// only when GLIBC_TUNABLES says glibc.malloc.hugetlb=1 at the start of the
// process. Nothing in the program can set that later, hence the restart.
#include <vpcontact/app/huge_pages.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#if defined(__linux__) && defined(__GLIBC__)
#  include <gnu/libc-version.h>
#  include <sys/auxv.h>
#  include <unistd.h>
#  define VPCONTACT_CAN_RESTART 1
#endif

namespace VPContact
{
  namespace
  {
    constexpr const char *tunable = "glibc.malloc.hugetlb";

    // Whether "major.minor" in @p version is at least 2.35, the first glibc
    // with the tunable.
    bool
    has_hugetlb_tunable(const std::string &version)
    {
      int                major = 0, minor = 0;
      char               dot = 0;
      std::istringstream in(version);
      if (!(in >> major >> dot >> minor) || dot != '.')
        return false;
      return major > 2 || (major == 2 && minor >= 35);
    }
  } // namespace



  std::string
  huge_page_tunables(const std::string &thp_enabled,
                     const std::string &glibc_version,
                     const char        *tunables,
                     const char        *request)
  {
    if (request == nullptr || std::string(request) != "1")
      return "";
    if (thp_enabled.find("[madvise]") == std::string::npos)
      return "";
    if (!has_hugetlb_tunable(glibc_version))
      return "";
    const std::string present = (tunables != nullptr ? tunables : "");
    if (present.find(tunable) != std::string::npos)
      return "";
    return present + (present.empty() ? "" : ":") + tunable + "=1";
  }



  void
  restart_with_huge_pages(char **argv)
  {
#ifdef VPCONTACT_CAN_RESTART
    // A set-user-ID start drops GLIBC_TUNABLES: it would restart forever.
    if (getauxval(AT_SECURE) != 0)
      return;
    std::ifstream     file("/sys/kernel/mm/transparent_hugepage/enabled");
    const std::string thp_enabled((std::istreambuf_iterator<char>(file)),
                                  std::istreambuf_iterator<char>());
    const char *const request = std::getenv("VPCONTACT_HUGE_PAGES");
    if (request != nullptr && std::string(request) != ""
        && std::string(request) != "0" && std::string(request) != "1")
      std::fprintf(stderr,
                   "vpcontact: VPCONTACT_HUGE_PAGES = %s is neither 1 (huge "
                   "pages for the heap) nor 0; the run keeps the system's "
                   "pages.\n",
                   request);
    const char       *present = std::getenv("GLIBC_TUNABLES");
    const std::string previous(present != nullptr ? present : "");
    const std::string value = huge_page_tunables(thp_enabled,
                                                 gnu_get_libc_version(),
                                                 present,
                                                 request);
    if (value.empty() || setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0)
      return;
    // Nothing is flushed or opened yet: the new process starts where this
    // one did, with the same arguments, environment and process id (which
    // mpirun waits for).
    execv("/proc/self/exe", argv);
    // The restart failed (no /proc, say): go on as before, 4 KiB pages.
    if (present != nullptr)
      setenv("GLIBC_TUNABLES", previous.c_str(), 1);
    else
      unsetenv("GLIBC_TUNABLES");
#else
    (void)argv;
#endif
  }
} // namespace VPContact
