// The submatrix of a distributed symmetric positive definite Trilinos matrix
// on the rows a solve leaves free, with the copies of vectors onto those rows
// and back: the damage solves run on it, since most of their rows are held.
#ifndef vpcontact_free_rows_system_h
#define vpcontact_free_rows_system_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * K_FF for a matrix K and a set F of free rows, numbered 0, 1, ... over
   * the ranks in the order of K's rows.
   *
   * While the damage is young, nearly every node sits at the upper bound
   * and is held in every damage solve (at 512^2 cells in the paper scene the
   * free nodes are 1 to 12 % of all up to t = 0.5). CG on the whole vector
   * with the held rows masked pays for every node in every iteration; CG on
   * K_FF pays for the free ones. Extracting K_FF visits only the free rows
   * of K (the columns of held rows are dropped: the unknowns vanish there),
   * so a new free set costs about one matrix-vector product on the free
   * rows, and an unchanged one costs nothing.
   */
  class FreeRowsSystem
  {
  public:
    /// Forget the free set, for a new matrix K.
    void
    clear();

    /**
     * Make K_FF for the free rows of @p matrix, i.e. its owned local
     * positions not in @p held. Returns whether K_FF changed on any rank
     * (collective): if not, a preconditioner of matrix() can be kept.
     */
    bool
    select(const LA::SparseMatrix          &matrix,
           const std::vector<unsigned int> &held);

    /// K_FF.
    const LA::SparseMatrix &
    matrix() const;

    /// A vector laid out like the rows of K_FF.
    void
    reinit_vector(LA::MPI::Vector &free_vector) const;

    /// The free entries of @p full (laid out like K's rows) into @p free.
    void
    restrict_to_free(const LA::MPI::Vector &full, LA::MPI::Vector &free) const;

    /// The entries of @p free into the free positions of @p full; the
    /// other entries of @p full are left alone.
    void
    extend_to_full(const LA::MPI::Vector &free, LA::MPI::Vector &full) const;

  private:
    /// The new global row of each column of K's local matrix, -1 where the
    /// row is held: the owned numbering imported into the columns.
    std::vector<int>
    free_numbers_of_columns(const Epetra_CrsMatrix &matrix) const;

    /// Fill K_FF from the free rows of @p full_matrix.
    void
    extract(const LA::SparseMatrix &full_matrix);

    /// The owned local positions of the free rows, in increasing order.
    std::vector<unsigned int> free_positions;
    /// The rows of K_FF that this rank owns, in the numbering of K_FF.
    IndexSet free_rows;

    LA::SparseMatrix free_matrix;
    bool             has_matrix = false;
  };
} // namespace VPContact

#endif
