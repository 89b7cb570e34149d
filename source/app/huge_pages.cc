// Transparent huge pages for the heap: on kernels that give them only to
// memory that asks for them, the program starts itself again with glibc's
// malloc told to ask.
//
// Why: a run allocates large arrays again and again (the factors of every
// factorization, the vectors of a new mesh, the patches and the text of
// every field file), and the kernel maps each 4 KiB page of them on its
// first touch, in a page fault: hundreds of thousands per run at 512^2
// cells, each one dearer inside a virtual machine. With 2 MiB pages there
// are up to 512 times fewer, and the factors' substitutions miss the TLB
// less. Most distributions set transparent huge pages to "madvise": only
// memory marked with madvise(MADV_HUGEPAGE) gets them, and glibc's malloc
// marks its memory only when GLIBC_TUNABLES says glibc.malloc.hugetlb=1 at
// the start of the process. Nothing in the program can set that later,
// hence the restart. doc/performance.md measures what it saves;
// VPCONTACT_HUGE_PAGES=0 turns it off.
#include <vpcontact/app/huge_pages.h>

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
                     const char        *opt_out)
  {
    if (opt_out != nullptr && std::string(opt_out) == "0")
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
    const char       *present = std::getenv("GLIBC_TUNABLES");
    const std::string previous(present != nullptr ? present : "");
    const std::string value
      = huge_page_tunables(thp_enabled,
                           gnu_get_libc_version(),
                           present,
                           std::getenv("VPCONTACT_HUGE_PAGES"));
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
