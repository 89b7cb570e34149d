// PETSc's SNES VI on the damage obstacle problem (see the header).
#include <vpcontact/damage/damage_obstacle_snes.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/petsc_tools.h>


namespace VPContact
{
  DamageObstacleSnes::~DamageObstacleSnes()
  {
    release();
  }



  void
  DamageObstacleSnes::release()
  {
    if (snes != nullptr)
      SNESDestroy(&snes);
    for (Vec *v : {&load, &z, &f, &lower, &upper})
      if (*v != nullptr)
        VecDestroy(v);
    if (K != nullptr)
      MatDestroy(&K);
  }



  void
  DamageObstacleSnes::initialize(const LA::SparseMatrix &matrix)
  {
    release();
    // One process reads the matrix where the program assembled it.
    K = view_in_petsc(matrix, 1);
    if (K == nullptr)
      K = copy_to_petsc(matrix, 1);
    VPContactPetsc(MatCreateVecs(K, &z, &f));
    for (Vec *v : {&load, &lower, &upper})
      VPContactPetsc(VecDuplicate(z, v));
    VPContactPetsc(VecSet(lower, 0.));
    VPContactPetsc(VecSet(upper, 1.));

    VPContactPetsc(SNESCreate(matrix.get_mpi_communicator(), &snes));
    VPContactPetsc(SNESSetType(snes, SNESVINEWTONRSLS));
    VPContactPetsc(SNESSetFunction(snes, f, &residual, this));
    VPContactPetsc(SNESSetJacobian(snes, K, K, &jacobian, this));
    VPContactPetsc(SNESVISetVariableBounds(snes, lower, upper));
    // F is linear: the full Newton step is the solution on its free set.
    SNESLineSearch line_search;
    VPContactPetsc(SNESGetLineSearch(snes, &line_search));
    VPContactPetsc(SNESLineSearchSetType(line_search, SNESLINESEARCHBASIC));
    KSP ksp;
    PC  pc;
    VPContactPetsc(SNESGetKSP(snes, &ksp));
    VPContactPetsc(KSPSetType(ksp, KSPCG));
    VPContactPetsc(KSPGetPC(ksp, &pc));
    VPContactPetsc(PCSetType(pc, PCBJACOBI));
    VPContactPetsc(
      PetscOptionsSetValue(nullptr, "-vpcontact_damage_sub_pc_type", "icc"));
    VPContactPetsc(SNESSetOptionsPrefix(snes, "vpcontact_damage_"));
    VPContactPetsc(SNESSetConvergenceTest(snes, &converged, this, nullptr));
    VPContactPetsc(SNESSetFromOptions(snes));
  }



  PetscErrorCode
  DamageObstacleSnes::converged(SNES     snes,
                                PetscInt iteration,
                                PetscReal,
                                PetscReal,
                                PetscReal            norm,
                                SNESConvergedReason *reason,
                                void                *context)
  {
    // The residual on the free nodes against the start's: a start that
    // solves the problem exactly (every node at a bound, F pushing onto
    // it) has 0 there, which cannot shrink relative to itself.
    auto *self = static_cast<DamageObstacleSnes *>(context);
    if (iteration == 0)
      self->initial_norm = norm;
    PetscReal relative;
    PetscCall(
      SNESGetTolerances(snes, nullptr, &relative, nullptr, nullptr, nullptr));
    *reason = (norm == 0. || norm <= relative * self->initial_norm) ?
                SNES_CONVERGED_FNORM_RELATIVE :
                SNES_CONVERGED_ITERATING;
    return 0;
  }



  PetscErrorCode
  DamageObstacleSnes::residual(SNES, Vec z, Vec f, void *context)
  {
    const auto *self = static_cast<const DamageObstacleSnes *>(context);
    PetscCall(MatMult(self->K, z, f));
    PetscCall(VecAXPY(f, -1., self->load));
    return 0;
  }



  PetscErrorCode
  DamageObstacleSnes::jacobian(SNES, Vec, Mat, Mat, void *)
  {
    return 0;
  }



  unsigned int
  DamageObstacleSnes::solve(const LA::MPI::Vector &b,
                            LA::MPI::Vector       &zeta,
                            const double           tolerance,
                            const unsigned int     max_iterations,
                            const unsigned int     max_linear_iterations)
  {
    Assert(snes != nullptr, ExcMessage("initialize() first."));
    copy_to_petsc(b, load);
    copy_to_petsc(zeta, z);
    VPContactPetsc(SNESSetTolerances(snes,
                                     0.,
                                     tolerance,
                                     0.,
                                     max_iterations,
                                     PETSC_DEFAULT));
    KSP ksp;
    VPContactPetsc(SNESGetKSP(snes, &ksp));
    VPContactPetsc(KSPSetTolerances(ksp,
                                    0.1 * tolerance,
                                    0.,
                                    PETSC_DEFAULT,
                                    max_linear_iterations));
    VPContactPetsc(SNESSolve(snes, nullptr, z));

    SNESConvergedReason reason;
    PetscInt            iterations;
    VPContactPetsc(SNESGetConvergedReason(snes, &reason));
    VPContactPetsc(SNESGetIterationNumber(snes, &iterations));
    AssertThrow(reason > 0,
                ExcMessage(
                  "The damage obstacle problem did not converge in PETSc's "
                  "SNES VI (reason "
                  + std::string(SNESConvergedReasons[reason]) + ") after "
                  + std::to_string(iterations)
                  + " Newton steps. Raise Damage/Maximum active set "
                    "iterations or Solver/Maximum linear iterations, or "
                    "choose Solver/Damage obstacle solver = active set."));
    copy_from_petsc(z, zeta);
    return iterations;
  }
} // namespace VPContact
