// The number of threads of the BLAS (OpenBLAS, looked up at run time): one
// for the many small calls of the substitutions, more for the dense products
// of a factorization.
#ifndef vpcontact_blas_threads_h
#define vpcontact_blas_threads_h

namespace VPContact
{
  /**
   * Set the number of threads of the BLAS where the BLAS in use can start
   * threads (OpenBLAS built with pthreads; with another BLAS this does
   * nothing). The program keeps it at one (run_application()): the
   * triangular solves of a factorization call the BLAS once per supernode,
   * on blocks too small for threads, and OpenBLAS's threads then wait for
   * cores that deal.II's threads or the other ranks hold.
   */
  void
  set_blas_threads(const unsigned int n_threads);

  /**
   * The BLAS with @p n_threads threads while this object lives (a
   * factorization, whose dense products are large enough for them), then
   * one again.
   */
  class BlasThreads
  {
  public:
    explicit BlasThreads(const unsigned int n_threads);
    ~BlasThreads();
    BlasThreads(const BlasThreads &) = delete;
    BlasThreads &
    operator=(const BlasThreads &)
      = delete;
  };

  /**
   * While this object lives, BlasThreads in the calling thread asks for at
   * most @p n_threads. A factorization in a second thread
   * (LinearSolver::initialize_in_background()) keeps to one core so:
   * OpenBLAS's own threads wait for work by spinning, and would take the
   * core that the calling thread's work beside the factorization needs.
   */
  class BlasThreadLimit
  {
  public:
    explicit BlasThreadLimit(const unsigned int n_threads);
    ~BlasThreadLimit();
    BlasThreadLimit(const BlasThreadLimit &) = delete;
    BlasThreadLimit &
    operator=(const BlasThreadLimit &)
      = delete;

  private:
    unsigned int previous;
  };
} // namespace VPContact

#endif
