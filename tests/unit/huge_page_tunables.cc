// Unit test: when the program restarts itself for huge pages, and with which
// GLIBC_TUNABLES (huge_page_tunables()): only where VPCONTACT_HUGE_PAGES=1
// asks for them, under the kernel's "madvise" mode, with a glibc of at least
// 2.35, keeping the user's other tunables, and never where the user set
// glibc.malloc.hugetlb.
#include <vpcontact/app/huge_pages.h>

#include <iostream>

using namespace VPContact;

void
show(const std::string &thp,
     const std::string &version,
     const char        *tunables,
     const char        *request)
{
  const std::string value = huge_page_tunables(thp, version, tunables, request);
  // The kernel's file ends in a newline; the line shows the text before it.
  std::cout << "enabled = \"" << thp.substr(0, thp.find('\n')) << "\", glibc "
            << version
            << ", GLIBC_TUNABLES = " << (tunables ? tunables : "(unset)")
            << ", VPCONTACT_HUGE_PAGES = " << (request ? request : "(unset)")
            << ": " << (value.empty() ? "no restart" : "restart with " + value)
            << std::endl;
}

int
main()
{
  const std::string madvise = "always [madvise] never\n";
  // Not asked for: no restart, whatever the kernel and glibc offer.
  show(madvise, "2.36", nullptr, nullptr);
  show(madvise, "2.36", nullptr, "0");
  show(madvise, "2.36", nullptr, "yes");
  // Asked for.
  show(madvise, "2.36", nullptr, "1");
  show(madvise, "2.35", nullptr, "1");
  show(madvise, "2.34", nullptr, "1");
  show(madvise, "3.0", nullptr, "1");
  show(madvise, "unknown", nullptr, "1");
  show("[always] madvise never\n", "2.36", nullptr, "1");
  show("always madvise [never]\n", "2.36", nullptr, "1");
  show("", "2.36", nullptr, "1");
  show(madvise, "2.36", "glibc.malloc.arena_max=2", "1");
  show(madvise, "2.36", "glibc.malloc.hugetlb=0", "1");
  show(madvise, "2.36", "glibc.malloc.hugetlb=1", "1");
  show(madvise, "2.36", "", "1");
}
