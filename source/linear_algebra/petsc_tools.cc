// PETSc's errors in the program's words, the copies between the program's
// Trilinos objects and PETSc's, and the PETSc operator of a matrix's row
// patterns.
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/petsc_tools.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace VPContact
{
  namespace
  {
    // The origin of the last PETSc error, in PETSc's words.
    std::string last_petsc_error;

    // Called by PETSc for the routine where an error starts and for every
    // caller it returns through; only the first says what went wrong.
    PetscErrorCode
    record_petsc_error(MPI_Comm,
                       int,
                       const char *function,
                       const char *,
                       PetscErrorCode code,
                       PetscErrorType type,
                       const char    *message,
                       void *)
    {
      if (type == PETSC_ERROR_INITIAL)
        {
          const char *text = nullptr;
          PetscErrorMessage(code, &text, nullptr);
          last_petsc_error = std::string(text != nullptr ? text : "")
                             + (message != nullptr && *message != '\0' ?
                                  std::string(" (") + message + ")" :
                                  std::string())
                             + " in " + function + "()";
        }
      return code;
    }

    std::string
    petsc_options_text()
    {
      const char *options = std::getenv("PETSC_OPTIONS");
      return options != nullptr ? options : "";
    }
  } // namespace



  std::string
  petsc_options_problem()
  {
    // PetscInitialize() reads the files named after -options_file (and
    // -options_file_yaml) and aborts on one it cannot open.
    std::istringstream words(petsc_options_text());
    std::string        word, file;
    while (words >> word)
      if ((word == "-options_file" || word == "-options_file_yaml"))
        {
          if (!(words >> file) || !std::ifstream(file))
            return "the environment variable PETSC_OPTIONS = '"
                   + petsc_options_text() + "' names the options file '" + file
                   + "' after " + word
                   + ", which cannot be read. Correct the path or unset "
                     "PETSC_OPTIONS.";
        }
    return "";
  }



  void
  install_petsc_error_messages()
  {
    PetscPushErrorHandler(record_petsc_error, nullptr);
  }



  std::string
  petsc_failure_message(const std::string &call, const PetscErrorCode code)
  {
    std::string message
      = "PETSc: " + call + " failed with error code " + std::to_string(code)
        + (last_petsc_error.empty() ? std::string() : ": " + last_petsc_error)
        + ".";
    const std::string options = petsc_options_text();
    if (!options.empty())
      message += " The environment variable PETSC_OPTIONS = '" + options
                 + "' sets PETSc options, and those prefixed vpcontact_ "
                   "reach this program's solvers: correct the option PETSc "
                   "names (its manual pages list the values each takes), or "
                   "unset PETSC_OPTIONS.";
    return message;
  }



  Mat
  copy_to_petsc(const LA::SparseMatrix &matrix,
                const unsigned int      dofs_per_node)
  {
    // PETSc's CSR preallocation wants each row's columns in ascending
    // global order; Epetra keeps them by local column index.
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    const int               n      = epetra.NumMyRows();
    std::vector<PetscInt>   row_start(n + 1, 0);
    std::vector<std::pair<PetscInt, PetscScalar>> row;
    std::vector<PetscInt>                         columns;
    std::vector<PetscScalar>                      values;
    columns.reserve(epetra.NumMyNonzeros());
    values.reserve(epetra.NumMyNonzeros());
    for (int r = 0; r < n; ++r)
      {
        int     length;
        double *entries;
        int    *local_columns;
        epetra.ExtractMyRowView(r, length, entries, local_columns);
        row.clear();
        for (int j = 0; j < length; ++j)
          row.emplace_back(epetra.ColMap().GID64(local_columns[j]), entries[j]);
        std::sort(row.begin(), row.end(), [](const auto &p, const auto &q) {
          return p.first < q.first;
        });
        for (const auto &[column, value] : row)
          {
            columns.push_back(column);
            values.push_back(value);
          }
        row_start[r + 1] = columns.size();
      }
    Mat A;
    VPContactPetsc(MatCreate(matrix.get_mpi_communicator(), &A));
    VPContactPetsc(MatSetSizes(A, n, n, matrix.m(), matrix.n()));
    VPContactPetsc(MatSetBlockSize(A, dofs_per_node));
    VPContactPetsc(MatSetType(A, MATAIJ));
    VPContactPetsc(MatSeqAIJSetPreallocationCSR(A,
                                                row_start.data(),
                                                columns.data(),
                                                values.data()));
    VPContactPetsc(MatMPIAIJSetPreallocationCSR(A,
                                                row_start.data(),
                                                columns.data(),
                                                values.data()));
    VPContactPetsc(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    VPContactPetsc(MatSetOption(A, MAT_SPD, PETSC_TRUE));
    return A;
  }



  Mat
  view_in_petsc(const LA::SparseMatrix &matrix,
                const unsigned int      dofs_per_node)
  {
    // On one process Epetra stores its rows as PETSc's SeqAIJ does: row
    // offsets, column indices sorted within each row, values, in three
    // arrays once its storage is optimized. The local column indices are
    // the global ones where the column map is the row map, a contiguous
    // range from 0.
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    int                    *row_start, *columns;
    double                 *entries;
    if (epetra.Comm().NumProc() != 1 || !epetra.Filled()
        || !epetra.StorageOptimized() || !epetra.RowMap().LinearMap()
        || epetra.RowMap().MinMyGID64() != 0
        || !epetra.ColMap().SameAs(epetra.RowMap())
        || epetra.ExtractCrsDataPointers(row_start, columns, entries) != 0)
      return nullptr;
    for (int r = 0; r < epetra.NumMyRows(); ++r)
      if (!std::is_sorted(columns + row_start[r], columns + row_start[r + 1]))
        return nullptr;
    static_assert(sizeof(PetscInt) == sizeof(int),
                  "a view needs PETSc's indices to be Epetra's ints");
    const PetscInt n = epetra.NumMyRows();
    Mat            A;
    VPContactPetsc(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF,
                                             n,
                                             n,
                                             row_start,
                                             columns,
                                             entries,
                                             &A));
    VPContactPetsc(MatSetBlockSize(A, dofs_per_node));
    VPContactPetsc(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    VPContactPetsc(MatSetOption(A, MAT_SPD, PETSC_TRUE));
    return A;
  }



  void
  copy_values_to_petsc(const LA::SparseMatrix &matrix, Mat A)
  {
    // An entry outside A's pattern would be an error, not a new entry:
    // the pattern, and with it what a factorization analysed, stays.
    VPContactPetsc(MatSetOption(A, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));
    const Epetra_CrsMatrix &epetra     = matrix.trilinos_matrix();
    const Epetra_Map       &column_map = epetra.ColMap();
    std::vector<PetscInt>   columns;
    for (int r = 0; r < epetra.NumMyRows(); ++r)
      {
        int     length;
        double *entries;
        int    *local_columns;
        epetra.ExtractMyRowView(r, length, entries, local_columns);
        columns.resize(length);
        for (int j = 0; j < length; ++j)
          columns[j] = column_map.GID64(local_columns[j]);
        const PetscInt row = epetra.RowMap().GID64(r);
        VPContactPetsc(MatSetValues(A,
                                    1,
                                    &row,
                                    length,
                                    columns.data(),
                                    entries,
                                    INSERT_VALUES));
      }
    VPContactPetsc(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    VPContactPetsc(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  }



  void
  copy_to_petsc(const LA::MPI::Vector &from, Vec to)
  {
    PetscScalar *entries;
    VPContactPetsc(VecGetArray(to, &entries));
    std::copy(from.begin(), from.end(), entries);
    VPContactPetsc(VecRestoreArray(to, &entries));
  }



  void
  copy_from_petsc(Vec from, LA::MPI::Vector &to)
  {
    const PetscScalar *entries;
    VPContactPetsc(VecGetArrayRead(from, &entries));
    std::copy(entries, entries + to.locally_owned_size(), to.begin());
    VPContactPetsc(VecRestoreArrayRead(from, &entries));
  }



  namespace
  {
    /// MATOP_MULT of create_pattern_product(): y = K x, the PETSc arrays
    /// viewed as Epetra vectors of the matrix's own layout.
    PetscErrorCode
    pattern_product(Mat product, Vec x, Vec y)
    {
      void *context = nullptr;
      PetscCall(MatShellGetContext(product, &context));
      const auto &patterns = *static_cast<const RowPatternMatrix *>(context);
      const PetscScalar *x_entries;
      PetscScalar       *y_entries;
      PetscCall(VecGetArrayRead(x, &x_entries));
      PetscCall(VecGetArray(y, &y_entries));
      int error = 0;
      try
        {
          // Epetra's views take non-const pointers; x is only read.
          const Epetra_Vector X(View,
                                patterns.OperatorDomainMap(),
                                const_cast<double *>(x_entries));
          Epetra_Vector       Y(View, patterns.OperatorRangeMap(), y_entries);
          error = patterns.Multiply(false, X, Y);
        }
      catch (...)
        {
          error = -1;
        }
      PetscCall(VecRestoreArray(y, &y_entries));
      PetscCall(VecRestoreArrayRead(x, &x_entries));
      PetscCheck(error == 0,
                 PETSC_COMM_SELF,
                 PETSC_ERR_LIB,
                 "the product from the matrix's row patterns failed "
                 "(Epetra error %d)",
                 error);
      return 0;
    }
  } // namespace



  Mat
  create_pattern_product(const RowPatternMatrix &patterns, MPI_Comm comm)
  {
    const PetscInt n_local  = patterns.OperatorRangeMap().NumMyElements();
    const PetscInt n_global = patterns.OperatorRangeMap().NumGlobalElements64();
    Mat            product;
    VPContactPetsc(MatCreateShell(comm,
                                  n_local,
                                  n_local,
                                  n_global,
                                  n_global,
                                  const_cast<RowPatternMatrix *>(&patterns),
                                  &product));
    VPContactPetsc(
      MatShellSetOperation(product,
                           MATOP_MULT,
                           reinterpret_cast<void (*)(void)>(&pattern_product)));
    VPContactPetsc(MatSetOption(product, MAT_SYMMETRIC, PETSC_TRUE));
    return product;
  }
} // namespace VPContact
