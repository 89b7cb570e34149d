// The solution of a symmetric positive definite system by a library: CG with
// an algebraic multigrid or incomplete Cholesky preconditioner, or a sparse
// factorization computed once and reused, in the linear algebra package
// (Trilinos or PETSc) that the parameter file names.
#ifndef vpcontact_spd_solver_h
#define vpcontact_spd_solver_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /// The package whose solvers and preconditioners a run uses.
  enum class LinearAlgebra
  {
    trilinos,
    petsc
  };

  /// How a system is solved.
  enum class SpdMethod
  {
    /// CG preconditioned by algebraic multigrid (Trilinos ML, PETSc GAMG).
    cg_amg,
    /// CG preconditioned by incomplete Cholesky on each rank's rows
    /// (Trilinos Ifpack IC, PETSc block Jacobi with ICC).
    cg_incomplete_cholesky,
    /// A factorization that gathers the matrix (Amesos KLU; PETSc MUMPS).
    direct,
    /// The distributed multifrontal factorization MUMPS.
    mumps,
    /// The supernodal Cholesky factorization of SuiteSparse CHOLMOD, on
    /// one process (SparseCholesky, for either package).
    cholesky
  };

  /**
   * What AMG should see as the (near) null space of a matrix: the rigid
   * motions of elasticity, each a vector laid out like the matrix rows, and
   * the number of unknowns at a node (which must be numbered together).
   * Without modes: the constants of a scalar problem.
   */
  struct NearNullSpace
  {
    unsigned int                 dofs_per_node = 1;
    std::vector<LA::MPI::Vector> modes;
  };

  /**
   * One symmetric positive definite matrix K and what solves with it: its
   * preconditioner or its factors, built once by initialize() and reused by
   * every solve(), since the matrices of the scheme change only with the
   * mesh, the time step or the stick set.
   *
   * The program keeps its fields in Trilinos vectors and assembles into a
   * Trilinos matrix; the PETSc implementation views the matrix as a PETSc
   * matrix in initialize() on one process and copies it on several, and
   * copies the vectors in each solve(), a pass over their entries.
   *
   * A solve may hold some rows: K x = b is then solved on the other rows
   * (the free ones) with x = 0 on the held ones. With incomplete Cholesky,
   * both packages solve on the free rows' submatrix K_FF with IC(0) of K_FF
   * (Trilinos: FreeRowsSystem, rebuilt only when the free set changes;
   * PETSc: MatCreateSubMatrix), so that an iteration costs what the free
   * rows cost, a few per cent of all in the damage solves. With AMG,
   * Trilinos runs CG on P K P + (I - P) preconditioned by P C P + (I - P),
   * P the projection onto the free rows and C the AMG of all of K, built
   * once. The factorizations solve with all rows.
   */
  class SpdSolver
  {
  public:
    virtual ~SpdSolver() = default;

    /**
     * Build the preconditioner or the factors of @p matrix, which must
     * outlive them; @p near_null_space is read by AMG only.
     */
    virtual void
    initialize(const LA::SparseMatrix &matrix,
               const NearNullSpace    &near_null_space)
      = 0;

    /**
     * Solve K x = b, on the rows that @p held (local positions of owned
     * rows) does not list; @p b and the start vector @p x must vanish on
     * the held rows. CG stops when the residual is at most @p control's
     * tolerance and throws SolverControl::NoConvergence at its iteration
     * limit. Returns the number of CG iterations, 1 for a solve with
     * factors.
     */
    virtual unsigned int
    solve(LA::MPI::Vector                 &x,
          const LA::MPI::Vector           &b,
          SolverControl                   &control,
          const std::vector<unsigned int> &held = {})
      = 0;

    /// One application of the preconditioner, or one solve with the
    /// factors: dst = C^{-1} src.
    virtual void
    precondition(LA::MPI::Vector &dst, const LA::MPI::Vector &src)
      = 0;

    /// Whether solve() uses factors (and ignores the tolerance).
    virtual bool
    is_direct() const = 0;

    /**
     * The values of the matrix given to initialize() changed in place; its
     * sparsity pattern did not (a stick set changed its constraints, or a
     * Newton step its tangent). Build the factors again from the new
     * values, keeping what depends on the pattern alone, and return true;
     * or return false, having changed nothing, where the method keeps
     * nothing (the caller then calls initialize()). CHOLMOD keeps its
     * fill-reducing order and its supernodes, PETSc's MUMPS its analysis
     * (order and symbolic factorization). AMG is built anew: ML's
     * ReComputePreconditioner() keeps the fine level's eigenvalue estimate
     * of the old values, and CG with it needed far more iterations than
     * with a new ML (doc/design.md).
     */
    virtual bool
    update_values()
    {
      return false;
    }

    /**
     * The values of the matrix given to initialize() changed in place and
     * the preconditioner or factors are kept: what the solver keeps of the
     * values for its products must follow them.
     */
    virtual void
    values_changed()
    {}
  };

  /// The solver of @p method in @p package. Throws where the package does
  /// not offer it, naming @p entry.
  std::unique_ptr<SpdSolver>
  create_spd_solver(const LinearAlgebra package,
                    const SpdMethod     method,
                    const std::string  &entry);

  /// "Trilinos" or "PETSc".
  std::string
  to_string(const LinearAlgebra package);
} // namespace VPContact

#endif
