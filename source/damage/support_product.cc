// SupportProduct: K x summed over the nonzero entries of x.
#include <vpcontact/damage/support_product.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

namespace VPContact
{
  void
  SupportProduct::initialize(const OwnedRows &rows)
  {
    matrix_rows      = &rows;
    n_owned          = rows.n_rows();
    const auto &halo = *rows.halo();
    serial_layout
      = (Utilities::MPI::n_mpi_processes(halo.get_mpi_communicator()) == 1);
    const unsigned int n_ghosts = halo.n_ghost_indices();
    ghost_x.assign(n_ghosts, 0.);
    send_buffer.assign(halo.n_import_indices(), 0.);

    // The entries in ghost columns, transposed in two passes over the
    // rows' ghost parts: count each column's entries, then place them (in
    // ascending rows, as a column of the rows lists them).
    const std::vector<unsigned int> &row_start = rows.row_start();
    const std::vector<unsigned int> &columns   = rows.columns();
    const auto for_each_ghost_entry            = [&](const auto &visit) {
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int e = row_start[i] + rows.owned_columns(i).size();
             e < row_start[i + 1];
             ++e)
          visit(i, columns[e] - n_owned, rows.values()[e]);
    };
    ghost_start.assign(n_ghosts + 1, 0);
    for_each_ghost_entry(
      [&](unsigned int, unsigned int g, double) { ++ghost_start[g + 1]; });
    for (unsigned int g = 0; g < n_ghosts; ++g)
      ghost_start[g + 1] += ghost_start[g];
    ghost_row.resize(ghost_start.back());
    ghost_value.resize(ghost_start.back());
    std::vector<unsigned int> next(ghost_start.begin(), ghost_start.end() - 1);
    for_each_ghost_entry([&](unsigned int i, unsigned int g, double v) {
      ghost_row[next[g]]     = i;
      ghost_value[next[g]++] = v;
    });
  }



  const OwnedRows &
  SupportProduct::rows() const
  {
    Assert(matrix_rows != nullptr, ExcMessage("initialize() first."));
    return *matrix_rows;
  }



  void
  SupportProduct::vmult(LA::MPI::Vector &y, const LA::MPI::Vector &x)
  {
    double *y_values = y.begin();
    std::fill(y_values, y_values + n_owned, 0.);
    const double *x_values = x.begin();
    for (unsigned int j = 0; j < n_owned; ++j)
      if (x_values[j] != 0.)
        add_column(y_values, j, x_values[j]);
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
        add_column(y_values, j, x_values[j]);
    add_ghost_columns(y_values, x);
  }



  void
  SupportProduct::add_ghost_columns(double *y_values, const LA::MPI::Vector &x)
  {
    if (serial_layout)
      return;
    const auto &halo = *matrix_rows->halo();
    halo.export_to_ghosted_array_start<double>(
      0,
      make_array_view<const double>(x.begin(), x.begin() + n_owned),
      make_array_view(send_buffer),
      make_array_view(ghost_x),
      requests);
    halo.export_to_ghosted_array_finish<double>(make_array_view(ghost_x),
                                                requests);
    for (unsigned int g = 0; g + 1 < ghost_start.size(); ++g)
      if (ghost_x[g] != 0.)
        for (unsigned int e = ghost_start[g]; e < ghost_start[g + 1]; ++e)
          y_values[ghost_row[e]] += ghost_value[e] * ghost_x[g];
  }



  ArrayView<const unsigned int>
  SupportProduct::rows_of_owned(const unsigned int position) const
  {
    return matrix_rows->owned_columns(position);
  }



  std::vector<unsigned int>
  SupportProduct::rows_of_ghosts() const
  {
    return ghost_row;
  }
} // namespace VPContact
