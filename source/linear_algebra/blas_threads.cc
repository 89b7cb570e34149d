// set_blas_threads() and BlasThreads: OpenBLAS's thread count, set through
// the function OpenBLAS exports, found at run time.
#include <vpcontact/linear_algebra/blas_threads.h>

#include <algorithm>
#include <dlfcn.h>
#include <initializer_list>
#include <limits>

namespace VPContact
{
  namespace
  {
    /// The limit of BlasThreadLimit in this thread.
    thread_local unsigned int blas_thread_limit
      = std::numeric_limits<unsigned int>::max();
  } // namespace



  void
  set_blas_threads(const unsigned int n_threads)
  {
    // openblas_set_num_threads() is OpenBLAS's own, not part of the BLAS
    // interface, so it is looked up at run time. Debian's OpenBLAS comes as
    // libblas.so.3 and libopenblas.so.0, each with its own thread count,
    // and the libraries may call either.
    using Setter = void (*)(int);
    for (const char *library : {"libblas.so.3", "libopenblas.so.0"})
      if (void *handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD))
        {
          if (const auto setter = reinterpret_cast<Setter>(
                dlsym(handle, "openblas_set_num_threads")))
            setter(static_cast<int>(n_threads));
          dlclose(handle);
        }
  }



  BlasThreads::BlasThreads(const unsigned int n_threads)
  {
    set_blas_threads(std::min(n_threads, blas_thread_limit));
  }



  BlasThreads::~BlasThreads()
  {
    set_blas_threads(1);
  }



  BlasThreadLimit::BlasThreadLimit(const unsigned int n_threads)
    : previous(blas_thread_limit)
  {
    blas_thread_limit = n_threads;
  }



  BlasThreadLimit::~BlasThreadLimit()
  {
    blas_thread_limit = previous;
  }
} // namespace VPContact
