// A sparse Cholesky factorization (SuiteSparse CHOLMOD) of a symmetric
// positive definite Trilinos matrix held whole on one process, and the solves
// with its factors.
#ifndef vpcontact_sparse_cholesky_h
#define vpcontact_sparse_cholesky_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cholmod.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * The factors L L^T = P K P^T of a symmetric positive definite matrix K,
   * computed once by factorize() and applied by solve() as often as needed:
   * the displacement matrix changes only with the mesh, the time step and
   * the stick set, and every step solves with it once.
   *
   * CHOLMOD orders the unknowns to reduce fill (AMD, and METIS or nested
   * dissection only when AMD fills too much) and factorizes large
   * matrices by supernodes, so most of its work is dense products in the
   * BLAS, and small ones column by column (simplicial), which is faster
   * there. CHOLMOD is called
   * directly rather than through PETSc, whose interface copies the matrix
   * into a PETSc matrix (a second copy of K in memory) and allocates and
   * copies the vectors of every solve. Only the
   * upper triangle of K is read; K must be symmetric.
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
     * message when it is not positive definite or memory runs out.
     */
    void
    factorize(const LA::SparseMatrix &matrix);

    /**
     * factorize() for @p matrix with the pattern of the last
     * factorization and new values: CHOLMOD's analysis (the fill-reducing
     * order and the supernodes, which depend on the pattern alone) is kept
     * and only the numeric factorization runs. The factors are those
     * factorize() would compute, bit for bit. After a factorization that
     * failed, factorize() itself.
     */
    void
    refactorize(const LA::SparseMatrix &matrix);

    /// Whether the last factorization went by supernodes.
    bool
    is_supernodal() const;

    /// dst = K^{-1} src.
    void
    solve(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const;

  private:
    void
    release();

    /// The numeric factorization of @p matrix with the analysis in factor,
    /// made first where @p analyze; throws as factorize() says.
    void
    factorize_numerically(const LA::SparseMatrix &matrix, const bool analyze);

    mutable cholmod_common common;
    cholmod_factor        *factor = nullptr;
    /// The result and the workspace of cholmod_solve2(), kept between
    /// solves.
    mutable cholmod_dense *solution    = nullptr;
    mutable cholmod_dense *workspace_y = nullptr;
    mutable cholmod_dense *workspace_e = nullptr;
  };
} // namespace VPContact

#endif
