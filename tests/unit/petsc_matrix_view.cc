// Checks view_in_petsc(), the PETSc matrix that reads a Trilinos matrix's
// entries where Epetra stores them: on one process it exists, its product
// is the Trilinos matrix's bit for bit, a change of the values in place
// shows in it without a copy, and PETSc's CG with GAMG on it converges as
// on a copy; on several processes there is no view (nullptr) and the copy
// (copy_to_petsc()) serves instead.
#include <vpcontact/linear_algebra/petsc_tools.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>
#include <petscksp.h>

#include "petsc_cg_iterations.h"
#include "q1_pattern_matrix.h"

using namespace dealii;
using namespace VPContact;

namespace
{
  /// x_i = sin(0.37 i) + 1e-3 i in a PETSc vector of A's layout, and
  /// the same in a Trilinos vector.
  void
  fill(Vec x, LA::MPI::Vector &v)
  {
    PetscInt first, last;
    VPContactPetsc(VecGetOwnershipRange(x, &first, &last));
    for (PetscInt i = first; i < last; ++i)
      {
        const double value = std::sin(0.37 * i) + 1e-3 * i;
        VPContactPetsc(VecSetValue(x, i, value, INSERT_VALUES));
        v[i] = value;
      }
    VPContactPetsc(VecAssemblyBegin(x));
    VPContactPetsc(VecAssemblyEnd(x));
    v.compress(VectorOperation::insert);
  }

  /// Whether PETSc's product with @p A is the Trilinos matrix's bit for bit
  /// (@p exact) or to round-off (1e-14 of its largest entry).
  bool
  same_product(Mat                     A,
               const LA::SparseMatrix &K,
               const IndexSet         &owned,
               const bool              exact = true)
  {
    Vec x, y;
    VPContactPetsc(MatCreateVecs(A, &x, &y));
    LA::MPI::Vector v(owned, MPI_COMM_WORLD), w(v);
    fill(x, v);
    VPContactPetsc(MatMult(A, x, y));
    K.vmult(w, v);
    const PetscScalar *entries;
    VPContactPetsc(VecGetArrayRead(y, &entries));
    const double tolerance = exact ? 0. : 1e-14 * w.linfty_norm();
    bool         same      = true;
    for (unsigned int i = 0; i < w.locally_owned_size(); ++i)
      same = same && std::abs(entries[i] - w.begin()[i]) <= tolerance;
    VPContactPetsc(VecRestoreArrayRead(y, &entries));
    VecDestroy(&x);
    VecDestroy(&y);
    return Utilities::MPI::min(same ? 1 : 0, MPI_COMM_WORLD) == 1;
  }

  /// PETSc's CG with GAMG on A for b = 1 (petsc_cg_iterations()).
  PetscInt
  cg_iterations(Mat A)
  {
    Vec b;
    VPContactPetsc(MatCreateVecs(A, nullptr, &b));
    VPContactPetsc(VecSet(b, 1.));
    const PetscInt iterations = petsc_cg_iterations(A, A, b);
    VecDestroy(&b);
    return iterations;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc,
                                       argv,
                                       numbers::invalid_unsigned_int);
  const bool      root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  Q1PatternMatrix grid(MPI_COMM_WORLD);

  Mat view = view_in_petsc(grid.K, 1);
  if (view == nullptr)
    {
      Mat        copy = copy_to_petsc(grid.K, 1);
      const bool same = same_product(copy, grid.K, grid.owned, false);
      if (root)
        std::cout << "several processes: no view, the copy's product "
                  << "as the matrix's to round-off: " << (same ? "yes" : "NO")
                  << std::endl;
      MatDestroy(&copy);
      return 0;
    }
  std::cout << "one process: a view; product identical: "
            << (same_product(view, grid.K, grid.owned) ? "yes" : "NO")
            << std::endl;

  // The values change in place; the view reads them without a copy. The
  // larger diagonal makes the matrix diagonally dominant, so that CG
  // below solves a positive definite system.
  grid.K *= 1.5;
  for (const auto i : grid.owned)
    grid.K.add(i, i, 100.);
  grid.K.compress(VectorOperation::add);
  std::cout << "after a change of the values: identical: "
            << (same_product(view, grid.K, grid.owned) ? "yes" : "NO")
            << std::endl;

  Mat copy = copy_to_petsc(grid.K, 1);
  VPContactPetsc(MatAssemblyBegin(view, MAT_FINAL_ASSEMBLY));
  VPContactPetsc(MatAssemblyEnd(view, MAT_FINAL_ASSEMBLY));
  const PetscInt on_view = cg_iterations(view), on_copy = cg_iterations(copy);
  std::cout << "CG with GAMG on the view: converges "
            << (on_view > 0 ? "yes" : "NO")
            << ", as on the copy: " << (on_view == on_copy ? "yes" : "NO")
            << std::endl;
  MatDestroy(&copy);
  MatDestroy(&view);
  return 0;
}
