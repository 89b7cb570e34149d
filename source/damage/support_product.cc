// SupportProduct: K x summed over the nonzero entries of x.
#include <vpcontact/damage/support_product.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

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



  std::vector<unsigned int>
  ghosted_positions_of_columns(const LA::SparseMatrix &matrix,
                               const Epetra_BlockMap  &ghosted_map)
  {
    const Epetra_BlockMap    &column_map = matrix.trilinos_matrix().ColMap();
    std::vector<unsigned int> positions(column_map.NumMyElements());
    for (unsigned int c = 0; c < positions.size(); ++c)
      {
        const int g
          = ghosted_map.LID(TrilinosWrappers::global_index(column_map, c));
        AssertThrow(g >= 0, ExcInternalError());
        positions[c] = g;
      }
    return positions;
  }



  void
  SupportProduct::initialize(const LA::SparseMatrix &matrix,
                             const IndexSet         &owned,
                             const MPI_Comm          communicator)
  {
    serial_layout = (Utilities::MPI::n_mpi_processes(communicator) == 1);
    x_ghosted.reinit(owned, columns_of_owned_rows(matrix, owned), communicator);
    const Epetra_BlockMap &ghosted_map = x_ghosted.trilinos_vector().Map();
    LA::MPI::Vector        owned_vector(owned, communicator);
    importer
      = std::make_unique<Epetra_Import>(ghosted_map,
                                        owned_vector.trilinos_vector().Map());

    const unsigned int n_ghosted = ghosted_map.NumMyElements();
    ghosted_of_owned.assign(owned.n_elements(), 0);
    ghost_positions.clear();
    for (unsigned int g = 0; g < n_ghosted; ++g)
      {
        const auto index = TrilinosWrappers::global_index(ghosted_map, g);
        if (owned.is_element(index))
          ghosted_of_owned[owned.index_within_set(index)] = g;
        else
          ghost_positions.push_back(g);
      }

    // The transpose of the owned rows, in two passes over their entries:
    // count the entries of each column, then place them.
    const std::vector<unsigned int> ghosted_of_column
      = ghosted_positions_of_columns(matrix, ghosted_map);
    const Epetra_CrsMatrix &K              = matrix.trilinos_matrix();
    const auto              for_each_entry = [&](const auto &visit) {
      for (int i = 0; i < K.NumMyRows(); ++i)
        {
          int     n_entries = 0;
          double *values    = nullptr;
          int    *indices   = nullptr;
          K.ExtractMyRowView(i, n_entries, values, indices);
          for (int e = 0; e < n_entries; ++e)
            visit(i, ghosted_of_column[indices[e]], values[e]);
        }
    };
    column_start.assign(n_ghosted + 1, 0);
    for_each_entry([&](int, unsigned int g, double) { ++column_start[g + 1]; });
    for (unsigned int g = 0; g < n_ghosted; ++g)
      column_start[g + 1] += column_start[g];
    row.resize(column_start.back());
    value.resize(column_start.back());
    std::vector<unsigned int> next(column_start.begin(),
                                   column_start.end() - 1);
    for_each_entry([&](int i, unsigned int g, double v) {
      row[next[g]]     = i;
      value[next[g]++] = v;
    });
  }



  void
  SupportProduct::vmult(LA::MPI::Vector &y, const LA::MPI::Vector &x)
  {
    // Rows are owned positions (the row map of the matrix lists the owned
    // indices in ascending order, as the owned vectors do).
    double            *y_values = y.begin();
    const unsigned int n_owned  = ghosted_of_owned.size();
    std::fill(y_values, y_values + n_owned, 0.);
    const double *x_values = x.begin();
    for (unsigned int j = 0; j < n_owned; ++j)
      if (x_values[j] != 0.)
        add_column(y_values, ghosted_of_owned[j], x_values[j]);
    add_ghost_columns(y_values, x);
  }



  void
  SupportProduct::vmult_on(LA::MPI::Vector                 &y,
                           const LA::MPI::Vector           &x,
                           const std::vector<unsigned int> &rows)
  {
    // The same columns in the same order as vmult(): x vanishes at the
    // owned positions outside rows.
    double *y_values = y.begin();
    for (const unsigned int i : rows)
      y_values[i] = 0.;
    const double *x_values = x.begin();
    for (const unsigned int j : rows)
      if (x_values[j] != 0.)
        add_column(y_values, ghosted_of_owned[j], x_values[j]);
    add_ghost_columns(y_values, x);
  }



  void
  SupportProduct::add_ghost_columns(double *y_values, const LA::MPI::Vector &x)
  {
    if (serial_layout)
      return;
    const int error = x_ghosted.trilinos_vector().Import(x.trilinos_vector(),
                                                         *importer,
                                                         Insert);
    AssertThrow(error == 0, ExcTrilinosError(error));
    const double *ghosted_values = x_ghosted.begin();
    for (const unsigned int g : ghost_positions)
      if (ghosted_values[g] != 0.)
        add_column(y_values, g, ghosted_values[g]);
  }



  ArrayView<const unsigned int>
  SupportProduct::rows_of_owned(const unsigned int position) const
  {
    const unsigned int g = ghosted_of_owned[position];
    return {row.data() + column_start[g],
            column_start[g + 1] - column_start[g]};
  }



  std::vector<unsigned int>
  SupportProduct::rows_of_ghosts() const
  {
    std::vector<unsigned int> rows;
    for (const unsigned int g : ghost_positions)
      rows.insert(rows.end(),
                  row.begin() + column_start[g],
                  row.begin() + column_start[g + 1]);
    return rows;
  }
} // namespace VPContact
