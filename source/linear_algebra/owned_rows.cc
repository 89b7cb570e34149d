// OwnedRows: this rank's rows of a matrix, in the ghosted layout of a
// deal.II partitioner.
#include <vpcontact/linear_algebra/owned_rows.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <utility>

namespace VPContact
{
  IndexSet
  columns_of_owned_rows(const LA::SparseMatrix &matrix, const IndexSet &owned)
  {
    const Epetra_BlockMap &column_map = matrix.trilinos_matrix().ColMap();
    IndexSet               columns(owned);
    for (int c = 0; c < column_map.NumMyElements(); ++c)
      columns.add_index(TrilinosWrappers::global_index(column_map, c));
    columns.compress();
    return columns;
  }



  void
  OwnedRows::reinit(const LA::SparseMatrix &matrix,
                    const IndexSet         &owned,
                    const MPI_Comm          communicator)
  {
    layout = std::make_shared<Utilities::MPI::Partitioner>(
      owned,
      columns_of_owned_rows(matrix, owned),
      communicator);
    const Epetra_CrsMatrix &K       = matrix.trilinos_matrix();
    const unsigned int      n_owned = owned.n_elements();
    AssertThrow(static_cast<unsigned int>(K.NumMyRows()) == n_owned,
                ExcInternalError());
    std::vector<unsigned int> position_of_column(K.NumMyCols());
    for (unsigned int c = 0; c < position_of_column.size(); ++c)
      position_of_column[c] = layout->global_to_local(
        TrilinosWrappers::global_index(K.ColMap(), c));

    // Sized exactly (no spare capacity of push_back's growth for the rest
    // of the run). Each row is sorted by position, which puts its owned
    // columns first: Epetra's own order is already that (the domain map's
    // indices first), so on one rank the sums over a row come in the order
    // of the Trilinos product.
    row_starts.resize(n_owned + 1);
    row_starts[0] = 0;
    column_positions.resize(K.NumMyNonzeros());
    entries.resize(K.NumMyNonzeros());
    std::vector<std::pair<unsigned int, double>> row;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        int     n_entries = 0;
        double *values    = nullptr;
        int    *indices   = nullptr;
        K.ExtractMyRowView(i, n_entries, values, indices);
        row.clear();
        for (int e = 0; e < n_entries; ++e)
          row.emplace_back(position_of_column[indices[e]], values[e]);
        std::stable_sort(row.begin(),
                         row.end(),
                         [](const auto &a, const auto &b) {
                           return a.first < b.first;
                         });
        unsigned int e = row_starts[i];
        for (const auto &[c, v] : row)
          {
            column_positions[e] = c;
            entries[e++]        = v;
          }
        row_starts[i + 1] = e;
      }
  }



  ArrayView<const unsigned int>
  OwnedRows::owned_columns(const unsigned int i) const
  {
    const unsigned int  n_owned = n_rows();
    const unsigned int *first   = column_positions.data() + row_starts[i];
    const unsigned int *last    = column_positions.data() + row_starts[i + 1];
    return {first,
            static_cast<std::size_t>(std::lower_bound(first, last, n_owned)
                                     - first)};
  }



  double
  OwnedRows::diagonal(const unsigned int i) const
  {
    for (unsigned int e = row_starts[i]; e < row_starts[i + 1]; ++e)
      if (column_positions[e] == i)
        return entries[e];
    return 0.;
  }
} // namespace VPContact
