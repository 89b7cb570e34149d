// FreeRowsSystem: the submatrix K_FF of the rows a solve leaves free, taken
// row by row from K's local matrix, and the vector copies onto it and back.
#include <vpcontact/linear_algebra/free_rows_system.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Vector.h>

namespace VPContact
{
  void
  FreeRowsSystem::clear()
  {
    free_positions.clear();
    has_matrix = false;
  }



  bool
  FreeRowsSystem::select(const LA::SparseMatrix          &matrix,
                         const std::vector<unsigned int> &held)
  {
    const MPI_Comm     communicator = matrix.get_mpi_communicator();
    const unsigned int n_owned      = matrix.local_size();
    std::vector<bool>  is_held(n_owned, false);
    for (const auto i : held)
      is_held[i] = true;
    std::vector<unsigned int> positions;
    positions.reserve(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      if (!is_held[i])
        positions.push_back(i);

    // The same answer on every rank, since building K_FF is collective.
    const bool changed
      = Utilities::MPI::logical_or(!has_matrix || positions != free_positions,
                                   communicator);
    if (!changed)
      return false;
    free_positions = std::move(positions);

    // K_FF's rows are numbered rank after rank: this rank's start is the
    // number of free rows on the ranks before it.
    const unsigned int n_free = free_positions.size();
    unsigned int       first  = 0;
    MPI_Exscan(&n_free, &first, 1, MPI_UNSIGNED, MPI_SUM, communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      first = 0;
    free_rows = IndexSet(Utilities::MPI::sum(n_free, communicator));
    free_rows.add_range(first, first + n_free);
    extract(matrix);
    has_matrix = true;
    return true;
  }



  std::vector<int>
  FreeRowsSystem::free_numbers_of_columns(const Epetra_CrsMatrix &matrix) const
  {
    // The row numbers of K_FF as values of a vector over K's rows, -1 on
    // held rows, brought to the columns by the matrix's own import (none
    // where the columns are the owned rows, on one rank). The numbers are
    // integers far below 2^53, exact in a double.
    Epetra_Vector numbers(matrix.RowMap());
    numbers.PutScalar(-1.);
    const int first
      = free_positions.empty() ? 0 : static_cast<int>(*free_rows.begin());
    for (unsigned int j = 0; j < free_positions.size(); ++j)
      numbers[free_positions[j]] = first + static_cast<int>(j);

    const Epetra_Vector *by_column = &numbers;
    Epetra_Vector        imported(matrix.ColMap());
    if (matrix.Importer() != nullptr)
      {
        imported.Import(numbers, *matrix.Importer(), Insert);
        by_column = &imported;
      }
    std::vector<int> column_numbers(matrix.NumMyCols());
    for (int c = 0; c < matrix.NumMyCols(); ++c)
      column_numbers[c] = static_cast<int>((*by_column)[c]);
    return column_numbers;
  }



  void
  FreeRowsSystem::extract(const LA::SparseMatrix &full_matrix)
  {
    const Epetra_CrsMatrix &matrix = full_matrix.trilinos_matrix();
    // Two passes over the free rows: the number of free columns in each
    // (Epetra's static profile wants it), then the entries themselves.
    const std::vector<int> column_numbers = free_numbers_of_columns(matrix);
    std::vector<int>       n_entries(free_positions.size());
    int                    longest = 0;
    for (unsigned int j = 0; j < free_positions.size(); ++j)
      {
        int     n;
        double *values;
        int    *columns;
        matrix.ExtractMyRowView(free_positions[j], n, values, columns);
        for (int e = 0; e < n; ++e)
          n_entries[j] += (column_numbers[columns[e]] >= 0);
        longest = std::max(longest, n);
      }

    const Epetra_Map map
      = free_rows.make_trilinos_map(full_matrix.get_mpi_communicator(), false);
    Epetra_CrsMatrix    submatrix(Copy, map, n_entries.data(), true);
    std::vector<double> row_values(longest);
    std::vector<int>    row_columns(longest);
    const int           first
      = free_positions.empty() ? 0 : static_cast<int>(*free_rows.begin());
    for (unsigned int j = 0; j < free_positions.size(); ++j)
      {
        int     n;
        double *values;
        int    *columns;
        matrix.ExtractMyRowView(free_positions[j], n, values, columns);
        int kept = 0;
        for (int e = 0; e < n; ++e)
          if (column_numbers[columns[e]] >= 0)
            {
              row_values[kept]  = values[e];
              row_columns[kept] = column_numbers[columns[e]];
              ++kept;
            }
        submatrix.InsertGlobalValues(first + static_cast<int>(j),
                                     kept,
                                     row_values.data(),
                                     row_columns.data());
      }
    submatrix.FillComplete();
    free_matrix.reinit(submatrix, true);
  }



  const LA::SparseMatrix &
  FreeRowsSystem::matrix() const
  {
    return free_matrix;
  }



  void
  FreeRowsSystem::reinit_vector(LA::MPI::Vector &free_vector) const
  {
    free_vector.reinit(free_rows, free_matrix.get_mpi_communicator());
  }



  void
  FreeRowsSystem::restrict_to_free(const LA::MPI::Vector &full,
                                   LA::MPI::Vector       &free) const
  {
    const double *from = full.begin();
    double       *to   = free.begin();
    for (unsigned int j = 0; j < free_positions.size(); ++j)
      to[j] = from[free_positions[j]];
  }



  void
  FreeRowsSystem::extend_to_full(const LA::MPI::Vector &free,
                                 LA::MPI::Vector       &full) const
  {
    const double *from = free.begin();
    double       *to   = full.begin();
    for (unsigned int j = 0; j < free_positions.size(); ++j)
      to[free_positions[j]] = from[j];
  }
} // namespace VPContact
