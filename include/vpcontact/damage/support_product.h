// The product of a sparse matrix with a vector that vanishes at most
// nodes, at the cost of its nonzero entries rather than of the matrix.
#ifndef vpcontact_support_product_h
#define vpcontact_support_product_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/array_view.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_Import.h>
#include <memory>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The indices a ghosted vector needs for the products of this rank's rows
   * of @p matrix: the owned ones (@p owned) and every column of the owned
   * rows. (Not the relevant dofs of the mesh: on adaptive meshes the rows
   * gather entries from other ranks' cells whose columns this rank does
   * not see.)
   */
  IndexSet
  columns_of_owned_rows(const LA::SparseMatrix &matrix, const IndexSet &owned);

  /**
   * For each local column of @p matrix, its position in the local storage
   * of a vector with the layout @p ghosted_map, which must hold it (see
   * columns_of_owned_rows()).
   */
  std::vector<unsigned int>
  ghosted_positions_of_columns(const LA::SparseMatrix &matrix,
                               const Epetra_BlockMap  &ghosted_map);

  /**
   * y = K x for a symmetric matrix K, summed column by column over the
   * entries of x that are not zero.
   *
   * Why: every damage solve needs K times the change of the nodes put at a
   * bound (nonzero at the few nodes that reached a bound in this
   * iteration) and K times the change of the solve (nonzero on the free
   * nodes: 1-12 % of the body while the damage is young in the paper
   * scene). Trilinos' product visits every row; at 512^2 cells the two
   * took 3.4 s of the 22.6 s of damage solves of a run.
   *
   * The columns of this rank's rows are kept by column (the transpose of
   * the local rows, in the layout of a ghosted vector), so that a nonzero
   * x_j adds K_ij x_j to the owned rows i that have j as a column. On
   * several ranks x is first imported into that ghosted layout: a ghost
   * entry of x is a column of some owned rows too.
   */
  class SupportProduct
  {
  public:
    /// Keep the owned rows of @p matrix by column. Once per matrix.
    void
    initialize(const LA::SparseMatrix &matrix,
               const IndexSet         &owned,
               const MPI_Comm          communicator);

    /// @p y = K @p x (both owned vectors of the matrix's row layout).
    void
    vmult(LA::MPI::Vector &y, const LA::MPI::Vector &x);

    /**
     * @p y = K @p x on the owned positions @p rows (ascending) alone, the
     * other entries of @p y left alone. @p x may be nonzero only at owned
     * positions in @p rows and at ghosts, and every row that such an entry
     * reaches must be in @p rows (see DamageWorkSet). The sums are those of
     * vmult(), in the same order, so the entries agree to the bit.
     */
    void
    vmult_on(LA::MPI::Vector                 &y,
             const LA::MPI::Vector           &x,
             const std::vector<unsigned int> &rows);

    /// The owned rows (positions) with an entry in the column of the owned
    /// position @p position: its neighbours in the matrix graph and itself.
    ArrayView<const unsigned int>
    rows_of_owned(const unsigned int position) const;

    /// The owned rows with an entry in the column of some ghost.
    std::vector<unsigned int>
    rows_of_ghosts() const;

  private:
    /// Add K_ij @p x_g to the owned rows i of the column at the ghosted
    /// position @p g.
    void
    add_column(double *y_values, const unsigned int g, const double x_g) const
    {
      for (unsigned int e = column_start[g]; e < column_start[g + 1]; ++e)
        y_values[row[e]] += value[e] * x_g;
    }

    /// Add K_ij x_j to the owned rows i of the ghost columns j (several
    /// ranks; nothing on one).
    void
    add_ghost_columns(double *y_values, const LA::MPI::Vector &x);

    /// For each position in the ghosted layout, its entries in the owned
    /// rows: (row, value), in CSR over the ghosted positions.
    std::vector<unsigned int> column_start;
    std::vector<unsigned int> row;
    std::vector<double>       value;
    /// The owned position of each owned entry of the ghosted layout, and
    /// the ghosted positions of the ghosts.
    std::vector<unsigned int> ghosted_of_owned;
    std::vector<unsigned int> ghost_positions;
    bool                      serial_layout = true;
    /// x in the ghosted layout, and the import into it (several ranks).
    LA::MPI::Vector                x_ghosted;
    std::unique_ptr<Epetra_Import> importer;
  };
} // namespace VPContact

#endif
