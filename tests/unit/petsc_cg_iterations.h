// What the unit tests of the PETSc matrices share: PETSc's CG with GAMG on
// a matrix, counted in iterations.
#ifndef vpcontact_tests_petsc_cg_iterations_h
#define vpcontact_tests_petsc_cg_iterations_h

#include <vpcontact/linear_algebra/petsc_tools.h>

#include <petscksp.h>

namespace VPContact
{
  /// PETSc's CG with GAMG built on @p A, its products from @p product (A
  /// itself, or an operator with A's products), from x = 0 to a residual
  /// of 1e-10 |b|: the iterations, or -1 where it does not converge.
  inline PetscInt
  petsc_cg_iterations(Mat product, Mat A, Vec b)
  {
    KSP solver;
    PC  pc;
    Vec x;
    VPContactPetsc(VecDuplicate(b, &x));
    VPContactPetsc(VecSet(x, 0.));
    VPContactPetsc(KSPCreate(PetscObjectComm(PetscObject(A)), &solver));
    VPContactPetsc(KSPSetOperators(solver, product, A));
    VPContactPetsc(KSPSetType(solver, KSPCG));
    VPContactPetsc(KSPGetPC(solver, &pc));
    VPContactPetsc(PCSetType(pc, PCGAMG));
    VPContactPetsc(PCSetUseAmat(pc, PETSC_TRUE));
    VPContactPetsc(KSPSetTolerances(solver, 1e-10, 0., 1e300, 1000));
    VPContactPetsc(KSPSolve(solver, b, x));
    PetscInt           iterations;
    KSPConvergedReason reason;
    VPContactPetsc(KSPGetIterationNumber(solver, &iterations));
    VPContactPetsc(KSPGetConvergedReason(solver, &reason));
    KSPDestroy(&solver);
    VecDestroy(&x);
    return reason > 0 ? iterations : -1;
  }
} // namespace VPContact

#endif
