// A sparse Cholesky factorization (SuiteSparse CHOLMOD) of a symmetric
// positive definite Trilinos matrix held whole on one process, and the
// number of BLAS threads its factorization uses.
#ifndef vpcontact_sparse_cholesky_h
#define vpcontact_sparse_cholesky_h

#include <vpcontact/supernode_partition.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <cholmod.h>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Set the number of threads of the BLAS, where the BLAS in use can start
   * threads (OpenBLAS, looked up at run time: with another BLAS, or the
   * serial OpenBLAS, this does nothing). The program keeps it at one (see
   * run_application()): the ranks of an mpirun, and the second thread of a
   * serial run, each have a core of their own.
   */
  void
  set_blas_threads(const unsigned int n_threads);

  /**
   * The factors L L^T = P K P^T of a symmetric positive definite matrix K,
   * computed once by factorize() and applied by solve() as often as
   * needed.
   *
   * CHOLMOD orders the unknowns to reduce fill (AMD, and METIS or nested
   * dissection only when AMD fills too much) and factorizes by supernodes,
   * so most of its work is dense matrix products (BLAS). A solve is a
   * forward and a backward triangular sweep over the supernodes, our own
   * (see forward_substitution()). Only the upper triangle of K
   * is read; K must be symmetric, which the displacement matrix is.
   */
  class SparseCholesky
  {
  public:
    SparseCholesky();
    ~SparseCholesky();
    SparseCholesky(const SparseCholesky &) = delete;
    SparseCholesky &
    operator=(const SparseCholesky &)
      = delete;

    /**
     * Factorize @p matrix, which must live on one process. Throws with a
     * message when it is not positive definite.
     */
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    /**
     * As factorize(), with @p blas_threads threads in the BLAS for the
     * dense products of the supernodes, where the BLAS can start threads
     * (OpenBLAS built with pthreads); back to one thread afterwards.
     */
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix,
              const unsigned int                    blas_threads);

    /**
     * dst = K^{-1} src. With @p n_threads = 2 the substitutions run on the
     * two groups of subtrees of the elimination tree at once (see
     * SupernodePartition); the result is the same bits as with one.
     */
    void
    solve(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src,
          const unsigned int                   n_threads = 1) const;

    /// Number of nonzeros of the factor L: the fill that the ordering
    /// left (0 before the first factorize()).
    double
    factor_nonzeros() const;

    /// How the substitutions split the supernodes (see solve()).
    const SupernodePartition &
    supernode_partition() const;

  private:
    void
    release();

    /// L^{-1} and L^{-T} applied in place to permuted.
    void
    forward_substitution(const unsigned int n_threads) const;
    void
    backward_substitution(const unsigned int n_threads) const;

    mutable cholmod_common common;
    cholmod_factor        *factor = nullptr;
    SupernodePartition     partition;
    /// The right-hand side and the solution in the order of L; for each
    /// group of subtrees the entries of a supernode's rows below its
    /// diagonal block, and what the group subtracts from the rows of the
    /// top. Kept between solves so that solve() allocates nothing.
    mutable std::vector<double>                permuted;
    mutable std::array<std::vector<double>, 2> below_values;
    mutable std::array<std::vector<double>, 2> top_sums;
  };
} // namespace VPContact

#endif
