// Unit test: when the program restarts itself for huge pages, and with which
// GLIBC_TUNABLES (huge_page_tunables()): only under the kernel's "madvise"
// mode, with a glibc of at least 2.35, keeping the user's other tunables, and
// never where the user set glibc.malloc.hugetlb or VPCONTACT_HUGE_PAGES=0.
#include <vpcontact/app/huge_pages.h>

#include <iostream>

using namespace VPContact;

void
show(const std::string &thp,
     const std::string &version,
     const char        *tunables,
     const char        *opt_out)
{
  const std::string value = huge_page_tunables(thp, version, tunables, opt_out);
  // The kernel's file ends in a newline; the line shows the text before it.
  std::cout << "enabled = \"" << thp.substr(0, thp.find('\n')) << "\", glibc "
            << version
            << ", GLIBC_TUNABLES = " << (tunables ? tunables : "(unset)")
            << ", VPCONTACT_HUGE_PAGES = " << (opt_out ? opt_out : "(unset)")
            << ": " << (value.empty() ? "no restart" : "restart with " + value)
            << std::endl;
}

int
main()
{
  const std::string madvise = "always [madvise] never\n";
  show(madvise, "2.36", nullptr, nullptr);
  show(madvise, "2.35", nullptr, nullptr);
  show(madvise, "2.34", nullptr, nullptr);
  show(madvise, "3.0", nullptr, nullptr);
  show(madvise, "unknown", nullptr, nullptr);
  show("[always] madvise never\n", "2.36", nullptr, nullptr);
  show("always madvise [never]\n", "2.36", nullptr, nullptr);
  show("", "2.36", nullptr, nullptr);
  show(madvise, "2.36", "glibc.malloc.arena_max=2", nullptr);
  show(madvise, "2.36", "glibc.malloc.hugetlb=0", nullptr);
  show(madvise, "2.36", "glibc.malloc.hugetlb=1", nullptr);
  show(madvise, "2.36", "", nullptr);
  show(madvise, "2.36", nullptr, "0");
  show(madvise, "2.36", nullptr, "1");
}
