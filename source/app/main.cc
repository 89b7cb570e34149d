// The vpcontact executable: it restarts itself with huge pages for its heap
// where VPCONTACT_HUGE_PAGES=1 asks for them and the kernel gives them only
// on request (huge_pages.h), then loads the library that holds the whole
// program and runs it.
//
// Why the library is loaded here rather than linked: it brings deal.II,
// Trilinos, PETSc and MPI, about 200 shared libraries whose loading takes
// about half a second. Linked, they would be loaded before main() and
// again after the restart; loaded here, once, after it.
#include <vpcontact/app/huge_pages.h>

#include <cstdio>
#include <dlfcn.h>

int
main(int argc, char **argv)
{
  VPContact::restart_with_huge_pages(argv);
  // RTLD_GLOBAL: the libraries Open MPI loads as plug-ins find MPI's
  // symbols in the global scope, as they do in a linked program.
  // RTLD_LAZY: as in a linked program, a function of the libraries is bound
  // when it is first called. deal.II's library alone has about 100,000 such
  // functions, most of which a run never calls; binding all of them at load
  // (RTLD_NOW) made every process start later (the figures are in the
  // message of the commit that chose RTLD_LAZY).
  void *const library = dlopen(VPCONTACT_LIBRARY, RTLD_LAZY | RTLD_GLOBAL);
  if (library == nullptr)
    {
      std::fprintf(stderr,
                   "vpcontact: cannot load its library: %s\n"
                   "Build the program again (cmake --build) or check that "
                   "the build folder was not moved.\n",
                   dlerror());
      return 1;
    }
  const auto run = reinterpret_cast<int (*)(int, char **)>(
    dlsym(library, "vpcontact_run_application"));
  if (run == nullptr)
    {
      std::fprintf(stderr,
                   "vpcontact: its library %s has no entry point: %s\n",
                   VPCONTACT_LIBRARY,
                   dlerror());
      return 1;
    }
  return run(argc, argv);
}
