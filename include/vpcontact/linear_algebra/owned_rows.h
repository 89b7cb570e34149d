// The owned rows of a sparse matrix in one local CSR array, their columns as
// positions in the ghosted layout of deal.II's partitioner: the one copy of
// the damage matrix that the program's own products and region solver read.
#ifndef vpcontact_owned_rows_h
#define vpcontact_owned_rows_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>

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
   * This rank's rows of a matrix, copied once out of the Trilinos matrix
   * they were assembled in.
   *
   * Why a copy of its own: the damage matrix K = M_L/k + kappa A is read
   * by the program's own kernels alone on the default path (the region
   * solver's CG and sweeps, SupportProduct, the graph of DamageBounds),
   * which each kept a copy in their own layout next to the Trilinos one:
   * three copies, 100 MB at 512^2 cells. They now share this one, and the
   * Trilinos matrix is released after it is taken (see
   * DamageSystem::initialize_preconditioner()).
   *
   * Row i is the owned position i (the row map of the matrix lists the
   * owned indices in ascending order, as the local storage of an owned
   * vector does). Its columns are positions in the ghosted layout of
   * halo(): the owned positions first, then the ghost entries. Within a
   * row the owned columns come first, in ascending order, and the ghost
   * columns after them, so that the owned part of a row is a prefix
   * (owned_columns()).
   */
  class OwnedRows
  {
  public:
    /// Copy the owned rows (@p owned) of @p matrix.
    void
    reinit(const LA::SparseMatrix &matrix,
           const IndexSet         &owned,
           const MPI_Comm          communicator);

    /// The number of owned rows.
    unsigned int
    n_rows() const
    {
      return row_starts.size() - 1;
    }

    /// The ghosted layout of the columns: the owned entries, then the
    /// other columns of the owned rows, as deal.II's partitioner numbers
    /// them.
    const std::shared_ptr<const Utilities::MPI::Partitioner> &
    halo() const
    {
      return layout;
    }

    /// Where row i's entries start in columns() and values(); row i ends
    /// where row i + 1 starts.
    const std::vector<unsigned int> &
    row_start() const
    {
      return row_starts;
    }

    const std::vector<unsigned int> &
    columns() const
    {
      return column_positions;
    }

    const std::vector<double> &
    values() const
    {
      return entries;
    }

    /// The owned columns of row @p i (ascending owned positions).
    ArrayView<const unsigned int>
    owned_columns(const unsigned int i) const;

    /// K_ii of row @p i.
    double
    diagonal(const unsigned int i) const;

  private:
    std::shared_ptr<const Utilities::MPI::Partitioner> layout;
    std::vector<unsigned int>                          row_starts{0};
    std::vector<unsigned int>                          column_positions;
    std::vector<double>                                entries;
  };
} // namespace VPContact

#endif
