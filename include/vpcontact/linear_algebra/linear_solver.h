// The linear solver of the displacement system, section "Solver": the
// package, the method and the tolerance, with the preconditioner or the
// factorization built once per matrix and reused by every step.
#ifndef vpcontact_linear_solver_h
#define vpcontact_linear_solver_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/spd_solver.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <future>
#include <memory>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Solver": solves K x = b for the symmetric positive definite
   * displacement matrix K with the package and method the parameter file
   * names (see SpdSolver).
   *
   * The matrix of the paper's velocity problem is constant while the mesh,
   * the time step and the stick set are fixed, so the preconditioner or the
   * factorization is built once in initialize() and reused by every solve().
   */
  class LinearSolver
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * With Linear solver = automatic: the method for a displacement system
     * of @p n_unknowns in @p dim dimensions on @p n_ranks processes over a
     * run of @p n_steps steps (SolverChoice; on every new mesh, before
     * initialize()); else nothing.
     */
    void
    choose(const types::global_dof_index n_unknowns,
           const unsigned int            dim,
           const unsigned int            n_ranks,
           const unsigned int            n_steps);

    /**
     * With Linear solver = automatic and a factorization chosen for the
     * run's steps: count the factorization anew that a change of the stick
     * set at step @p step asks for, and once they come more often than the
     * steps repay (SolverChoice::refactorizations_outweigh()), take CG with
     * AMG for the rest of the run. Returns whether it switched; the caller
     * then initializes the solver with the rigid motions.
     */
    bool
    switch_after_refactorization(const unsigned int step);

    /// The state of the automatic choice that a checkpoint keeps: the
    /// factorizations anew so far and whether the run switched to AMG.
    std::pair<unsigned int, bool>
    choice_state() const;

    /// Set that state, after choose() on the mesh of a resumed run; with
    /// @p switched the method is CG with AMG from here on.
    void
    restore_choice_state(const unsigned int n_refactorizations,
                         const bool         switched);

    /// The method for the header, and why where it was chosen.
    std::string
    description() const;

    /**
     * Build the preconditioner or factorization of @p matrix; @p
     * near_null_space are the rigid motions, for AMG. With AMG it refers to
     * both until clear() or the next initialize() (a rebuild after
     * matrix_changed() uses them), with a factorization to the matrix.
     *
     * Called again for the same matrix and near null space, the matrix's
     * values changed in place and its pattern not (a new pattern comes
     * after clear(), as DisplacementProblem::setup() does it): the solver
     * then keeps what depends on the pattern alone (SpdSolver::
     * update_values(): CHOLMOD its order and supernodes, PETSc's MUMPS its
     * analysis).
     */
    void
    initialize(const LA::SparseMatrix &matrix,
               const NearNullSpace    &near_null_space);

    /// How often initialize() built the preconditioner or factors anew,
    /// and how often it updated them (for the tests).
    std::pair<unsigned int, unsigned int>
    n_builds_and_updates() const
    {
      return {n_builds, n_updates};
    }

    /**
     * initialize() in a second thread where the method is Cholesky (one
     * process; else initialize() itself, with @p near_null_space for
     * AMG): returns at once, so that the
     * caller can go on with work that needs neither the factors nor the
     * matrix, which must not change until the factors are done. Every
     * function of this class that uses the factors waits for them first
     * (wait_for_factors()). The second thread calls no MPI function, and
     * the BLAS keeps to one thread there (BlasThreadLimit).
     */
    void
    initialize_in_background(const LA::SparseMatrix &matrix,
                             const NearNullSpace    &near_null_space);

    /// Wait for the factors of initialize_in_background(), if they are
    /// being built; rethrows what the factorization threw.
    void
    wait_for_factors();

    /// Release the preconditioner or factorization (before the matrix it
    /// refers to is re-initialised or destroyed); a factorization still
    /// running in the background is waited for and dropped, with any error
    /// it met.
    void
    clear();

    /**
     * Solve K x = b. @p x is the start vector for CG. Returns the number of
     * iterations (1 for a factorization, 0 for b = 0). Throws with a message
     * naming the Solver parameters to change when CG does not reach the
     * tolerance.
     */
    unsigned int
    solve(LA::MPI::Vector &x, const LA::MPI::Vector &b);

    /**
     * Whether solve_in_background() may be called: the factors of
     * Solver/Linear solver = Cholesky (one process) for the matrix as it
     * was given to initialize(). After matrix_changed() a solve is CG on
     * the changed matrix, which is left to solve().
     */
    bool
    solves_in_background() const;

    /**
     * solve() with its substitutions in a second thread, so that the
     * caller can work beside them: the future's get() returns the number of
     * iterations (1, or 0 for b = 0) and rethrows what the solve threw.
     * The checks of @p b (finite, its norm) run in the calling thread
     * before it returns, since they may call MPI; the second thread only
     * calls the factors' substitutions (CHOLMOD, no MPI). Until get()
     * returns, @p x, @p b and the factors belong to the second thread: the
     * caller must not touch the vectors nor call a function of this solver
     * that is not const (the const ones, such as tolerance(), read only
     * what the second thread does not write). @p then, if given, runs in
     * the second thread after the substitutions, with @p x solved (the
     * caller's work that only needs x); it must not call MPI.
     */
    std::future<unsigned int>
    solve_in_background(LA::MPI::Vector             &x,
                        const LA::MPI::Vector       &b,
                        const std::function<void()> &then = {});

    /**
     * The near null space that a rebuild after matrix_changed() hands AMG:
     * the caller's object given to initialize(), which must outlive the
     * solver's use of it (nullptr for the other methods).
     */
    const NearNullSpace *
    rebuild_near_null_space() const
    {
      return null_space;
    }

    /**
     * The matrix given to initialize() changed in place by a little (the
     * slip stiffness of a friction iteration). Later solves run deal.II's CG
     * on the changed matrix, preconditioned by the preconditioner or the
     * factors built for it in initialize(), until the next initialize(); a
     * solve where that does not converge within a few times the iterations
     * of a fresh solve builds them anew for the changed matrix and solves
     * with those. The solver's products with the matrix take in the new
     * values (SpdSolver::values_changed()): every change of the values
     * that a later solve is to see must be followed by this call or by
     * initialize().
     */
    void
    matrix_changed();

    /**
     * matrix_changed() for a change of the values in @p changed_rows rows
     * and the same columns (a change of the stick set: the constraints of
     * its nodes' unknowns), counted with those of earlier calls since the
     * last initialize().
     */
    void
    rows_changed(const unsigned int changed_rows);

    /**
     * Whether CG preconditioned by the preconditioner or factors of the
     * matrix as it was at initialize() is expected to solve the matrix
     * after @p changed_rows more rows and columns changed (see
     * rows_changed()) within the iterations after which
     * preconditioner_outdated() rebuilds them anyway. The change since
     * initialize() has rank at most twice its rows, and CG preconditioned
     * by the exact inverse of a matrix that differs from the system by a
     * change of rank r converges in at most r + 1 iterations; AMG's
     * iterations grow by about as many.
     */
    bool
    keeps_through(const unsigned int changed_rows) const;

    /// Whether the preconditioner or factors were kept through
    /// rows_changed() since initialize().
    bool
    kept_through_changed_rows() const
    {
      return rows_changed_since_initialize > 0;
    }

    /// Whether a solve after matrix_changed() needed so many more
    /// iterations than the solves before it that initialize() pays off.
    bool
    preconditioner_outdated() const;

    /// One application of the preconditioner or one solve with the factors.
    void
    precondition(LA::MPI::Vector &dst, const LA::MPI::Vector &src);

    /// Whether the method is a factorization.
    bool
    is_direct() const;

    /// The package of Solver/Linear algebra, for the damage solves, which
    /// use the same one.
    LinearAlgebra
    package() const;

    double
    tolerance() const;

    /**
     * Let CG stop at sqrt(Solver/Relative tolerance) instead of the
     * tolerance (@p loose), until called again with false: the friction
     * iteration solves this far while its sets still change. A
     * factorization solves exactly either way.
     */
    void
    set_loose_tolerance(const bool loose);

    unsigned int
    iteration_limit() const;

  private:
    LinearAlgebra linear_algebra = LinearAlgebra::trilinos;
    SpdMethod     method         = SpdMethod::cg_amg;
    /// Linear solver = automatic, and why choose() took the method.
    bool        automatic = false;
    std::string reason;
    /// The automatic choice's refactorization count: whether it may switch
    /// to AMG, after how many steps per factorization, the count so far
    /// and whether it switched (kept through the meshes of a run).
    bool                       may_switch         = false;
    double                     steps_needed       = 0;
    unsigned int               n_refactorizations = 0;
    bool                       switched           = false;
    double                     relative_tolerance = 1e-10;
    bool                       loose              = false;
    unsigned int               max_iterations     = 1000;
    std::unique_ptr<SpdSolver> solver;
    /// The factorization of initialize_in_background() while it runs
    /// (declared after solver: destroyed first, it waits for the thread
    /// before the solver goes).
    std::future<void> factorizing;
    /// The matrix of initialize(), and whether it changed since.
    const LA::SparseMatrix *matrix                   = nullptr;
    bool                    changed_since_initialize = false;
    /// Iterations of the last solve before and after the matrix changed.
    unsigned int iterations_before = 0;
    unsigned int iterations_after  = 0;
    /// The rows that rows_changed() reported since initialize().
    unsigned int rows_changed_since_initialize = 0;

    /// The iterations beyond which preconditioner_outdated() holds.
    unsigned int
    rebuild_threshold() const;

    /// initialize() again with the matrix and near null space it has.
    void
    rebuild();

    /// The preconditioner or factors of @p matrix, built anew.
    void
    build(const LA::SparseMatrix &matrix, const NearNullSpace &near_null_space);

    /// SpdSolver::update_values() where initialize() is called again for
    /// the matrix the solver was built for; returns whether it did.
    bool
    update_values(const LA::SparseMatrix &matrix,
                  const NearNullSpace    &near_null_space);

    /// The Epetra matrix and its number of entries when the solver was
    /// built: a matrix that differs in either was reinitialised.
    const void             *built_on       = nullptr;
    types::global_dof_index built_nonzeros = 0;
    unsigned int            n_builds       = 0;
    unsigned int            n_updates      = 0;

    /// AMG's near null space of initialize(), for a rebuild after
    /// matrix_changed() (the caller's, not a copy).
    const NearNullSpace *null_space = nullptr;

    /// |b|, after checking that @p b is finite.
    static double
    checked_norm(const LA::MPI::Vector &b);

    /// CG on the changed matrix with the old preconditioner; false (and
    /// @p x unchanged) where it does not converge within a few times the
    /// iterations of a fresh solve.
    bool
    solve_changed_matrix(LA::MPI::Vector       &x,
                         const LA::MPI::Vector &b,
                         const double           tolerance,
                         unsigned int          &iterations);
  };
} // namespace VPContact

#endif
