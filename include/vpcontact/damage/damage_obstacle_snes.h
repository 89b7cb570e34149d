// The damage obstacle problem solved whole by PETSc's reduced-space
// semismooth Newton method for variational inequalities (SNES VI), the
// alternative to the program's primal-dual active set around CG solves.
#ifndef vpcontact_damage_obstacle_snes_h
#define vpcontact_damage_obstacle_snes_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <petscsnes.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * Find zeta with 0 <= zeta <= 1 and K zeta - b = lambda, lambda >= 0 where
   * zeta = 0, lambda <= 0 where zeta = 1 and lambda = 0 between: the
   * discrete damage problem of step 4 with its lumped mass, the same
   * complementarity problem that DamageBounds decides node by node. PETSc's
   * SNESVINEWTONRSLS takes full Newton steps on the nodes off their bounds
   * (CG with block Jacobi / ICC on their submatrix) and moves nodes onto and
   * off the bounds between them, which for this linear F is the primal-dual
   * active set method again, started from the bounds that zeta_{n-1}
   * touches. Options prefixed "vpcontact_damage_" in PETSC_OPTIONS reach it
   * (e.g. -vpcontact_damage_snes_monitor).
   */
  class DamageObstacleSnes
  {
  public:
    ~DamageObstacleSnes();

    /// Take K (which changes with the mesh and the time step only) into
    /// PETSc, a view of @p matrix on one process (which must then outlive
    /// it) and a copy on several, and set up the Newton method around it.
    void
    initialize(const LA::SparseMatrix &matrix);

    /**
     * Solve from the start vector @p zeta (zeta_{n-1}), which gets the
     * solution. Newton stops once the residual on the free nodes is
     * @p tolerance times that of the start; each step's CG stops at a tenth
     * of that, relative to its right-hand side. Returns the Newton steps;
     * throws a message naming the parameters after @p max_iterations.
     */
    unsigned int
    solve(const LA::MPI::Vector &b,
          LA::MPI::Vector       &zeta,
          const double           tolerance,
          const unsigned int     max_iterations,
          const unsigned int     max_linear_iterations);

  private:
    /// F(z) = K z - b.
    static PetscErrorCode
    residual(SNES snes, Vec z, Vec f, void *context);

    /// The Jacobian is K, set once.
    static PetscErrorCode
    jacobian(SNES snes, Vec z, Mat J, Mat P, void *context);

    /// Converged once the residual on the free nodes is the relative
    /// tolerance times the first, or 0.
    static PetscErrorCode
    converged(SNES                 snes,
              PetscInt             iteration,
              PetscReal            solution_norm,
              PetscReal            step_norm,
              PetscReal            norm,
              SNESConvergedReason *reason,
              void                *context);

    void
    release();

    PetscReal initial_norm = 0.;

    Mat  K     = nullptr;
    Vec  load  = nullptr;
    Vec  z     = nullptr;
    Vec  f     = nullptr;
    Vec  lower = nullptr;
    Vec  upper = nullptr;
    SNES snes  = nullptr;
  };
} // namespace VPContact

#endif
