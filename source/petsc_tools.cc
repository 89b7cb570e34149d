// The copies between the program's Trilinos objects and PETSc's.
#include <vpcontact/petsc_tools.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <algorithm>
#include <utility>
#include <vector>

namespace VPContact
{
  Mat
  copy_to_petsc(const TrilinosWrappers::SparseMatrix &matrix,
                const unsigned int                    dofs_per_node)
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



  void
  copy_to_petsc(const TrilinosWrappers::MPI::Vector &from, Vec to)
  {
    PetscScalar *entries;
    VPContactPetsc(VecGetArray(to, &entries));
    std::copy(from.begin(), from.end(), entries);
    VPContactPetsc(VecRestoreArray(to, &entries));
  }



  void
  copy_from_petsc(Vec from, TrilinosWrappers::MPI::Vector &to)
  {
    const PetscScalar *entries;
    VPContactPetsc(VecGetArrayRead(from, &entries));
    std::copy(entries, entries + to.locally_owned_size(), to.begin());
    VPContactPetsc(VecRestoreArrayRead(from, &entries));
  }
} // namespace VPContact
