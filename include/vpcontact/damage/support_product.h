// The product of a sparse matrix with a vector that vanishes at most
// nodes, at the cost of its nonzero entries rather than of the matrix.
#ifndef vpcontact_support_product_h
#define vpcontact_support_product_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/owned_rows.h>

#include <deal.II/base/array_view.h>
#include <deal.II/lac/trilinos_vector.h>

#include <mpi.h>
#include <vector>

namespace VPContact
{
  using namespace dealii;

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
   * K is symmetric, so the column j of the owned rows is the owned part of
   * row j (OwnedRows keeps it as a prefix of the row, in ascending order):
   * a nonzero x_j adds K_ji x_j to the owned rows i among row j's columns.
   * On several ranks a ghost entry x_g is a column of some owned rows too;
   * those few entries are kept transposed here, and x's ghost entries come
   * through the partitioner of the rows.
   */
  class SupportProduct
  {
  public:
    /// Read K from @p rows (kept by reference: they must outlive this
    /// object's use), and transpose its entries in ghost columns.
    void
    initialize(const OwnedRows &rows);

    /// The rows the product reads.
    const OwnedRows &
    rows() const;

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
    /// Add K_ij @p x_j to the owned rows i of the owned column @p j (the
    /// owned prefix of row j, by symmetry).
    void
    add_column(double *y_values, const unsigned int j, const double x_j) const
    {
      const unsigned int *columns = matrix_rows->columns().data();
      const double       *values  = matrix_rows->values().data();
      const unsigned int  last    = matrix_rows->row_start()[j + 1];
      for (unsigned int e = matrix_rows->row_start()[j];
           e < last && columns[e] < n_owned;
           ++e)
        y_values[columns[e]] += values[e] * x_j;
    }

    /// Add K_ig x_g to the owned rows i of the ghost columns g (several
    /// ranks; nothing on one).
    void
    add_ghost_columns(double *y_values, const LA::MPI::Vector &x);

    const OwnedRows *matrix_rows   = nullptr;
    unsigned int     n_owned       = 0;
    bool             serial_layout = true;
    /// The owned rows of each ghost column: (row, K_ig), in CSR over the
    /// halo's ghost entries.
    std::vector<unsigned int> ghost_start;
    std::vector<unsigned int> ghost_row;
    std::vector<double>       ghost_value;
    /// x's ghost entries, and the exchange's send buffer and requests.
    std::vector<double>      ghost_x;
    std::vector<double>      send_buffer;
    std::vector<MPI_Request> requests;
  };
} // namespace VPContact

#endif
