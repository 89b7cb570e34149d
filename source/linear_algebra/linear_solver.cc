// The section "Solver" and the solution of the displacement system.
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/blas_threads.h>
#include <vpcontact/linear_algebra/finite_values.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>
#include <vpcontact/linear_algebra/solver_choice.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/lac/solver_cg.h>

#include <algorithm>
#include <cmath>
#include <future>

namespace VPContact
{
  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      prm.declare_entry(
        "Linear algebra",
        "Trilinos",
        Patterns::Selection("Trilinos|PETSc"),
        "The package of the solvers and preconditioners of the displacement "
        "and damage systems. 'Trilinos': ML algebraic multigrid, Ifpack "
        "incomplete Cholesky, Amesos KLU and MUMPS. 'PETSc': GAMG, block "
        "Jacobi with ICC, and MUMPS; 'Cholesky' is the same with both. "
        "options prefixed 'vpcontact_' in PETSC_OPTIONS reach its "
        "preconditioners. Both give the same results to the solver "
        "tolerance; see doc/performance.md for what each costs.");
      prm.declare_entry(
        "Linear solver",
        "automatic",
        Patterns::Selection("automatic|CG with AMG|direct|MUMPS|Cholesky"),
        "'automatic': a factorization ('Cholesky' on one process, 'MUMPS' "
        "on several) where the run's steps repay its one-time cost, else "
        "'CG with AMG'. A factorization is taken below 20,000 displacement "
        "unknowns, never beyond 2,000,000 in 2D and 210,000 in 3D (its "
        "factors' memory) nor on several processes in 2D below 100,000, and "
        "in between from a number of steps (Time/End time over Time step) "
        "that grows with the unknowns: about 8 in 2D on one process, 46 in "
        "3D at 100,000 unknowns (doc/performance.md, scripts/bench_solvers). "
        "The header names the choice and why. Each change of the stick set "
        "factorizes anew; once they come more often than the steps repay, "
        "the run takes 'CG with AMG' for its remaining steps and says so "
        "(for a scene whose base slips, name 'CG with AMG'). "
        "'CG with AMG': "
        "conjugate gradients preconditioned by algebraic "
        "multigrid whose near null space holds the rigid motions; scales to "
        "large meshes and many ranks, and is the method for 3D. 'direct': "
        "a factorization that gathers the matrix (Amesos KLU with Trilinos, "
        "MUMPS with PETSc), for small meshes. 'MUMPS': the distributed "
        "multifrontal factorization, for medium meshes under mpirun. "
        "'Cholesky': the sparse Cholesky factorization of SuiteSparse "
        "CHOLMOD on one process, by supernodes for large matrices "
        "(CHOLMOD's own substitutions, run beside the damage "
        "step in a second thread), the fastest choice for a serial 2D run. A "
        "factorization is computed once per matrix and reused by every "
        "step, and again whenever the stick set changes.");
      prm.declare_entry("Relative tolerance",
                        "1e-10",
                        Patterns::Double(0, 1),
                        "CG stops when the residual norm is below this "
                        "fraction of the right-hand side norm.");
      prm.declare_entry("Maximum linear iterations",
                        "1000",
                        Patterns::Integer(1),
                        "CG gives up (and the run stops with a message) after "
                        "this many iterations.");
    }
    prm.leave_subsection();
  }



  void
  LinearSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    linear_algebra
      = (prm.get("Linear algebra") == "PETSc" ? LinearAlgebra::petsc :
                                                LinearAlgebra::trilinos);
    const std::string name = prm.get("Linear solver");
    automatic              = (name == "automatic");
    method = (name == "CG with AMG" || automatic ? SpdMethod::cg_amg :
              name == "Cholesky"                 ? SpdMethod::cholesky :
              name == "MUMPS"                    ? SpdMethod::mumps :
                                                   SpdMethod::direct);
    relative_tolerance = prm.get_double("Relative tolerance");
    max_iterations     = prm.get_integer("Maximum linear iterations");
    prm.leave_subsection();
    // At 1 the start vector already meets the tolerance, and no step would
    // be solved at all.
    VPContactCheckParameter(relative_tolerance > 0 && relative_tolerance < 1,
                            "Solver/Relative tolerance",
                            relative_tolerance,
                            "must lie in (0, 1), e.g. 1e-10.");
    VPContactCheckParameter(method != SpdMethod::cholesky
                              || Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
                                   == 1,
                            "Solver/Linear solver",
                            name,
                            "factorizes on one process only: run without "
                            "mpirun, or choose MUMPS "
                            "(distributed) or CG with AMG.");
  }



  void
  LinearSolver::choose(const types::global_dof_index n_unknowns,
                       const unsigned int            dim,
                       const unsigned int            n_ranks,
                       const unsigned int            n_steps)
  {
    // A run that switched to AMG keeps it on the meshes that adapting
    // gives it: its stick set goes on changing there.
    if (!automatic || switched)
      return;
    const SolverChoice choice(n_unknowns, dim, n_ranks, n_steps);
    method       = choice.method();
    reason       = choice.reason();
    may_switch   = choice.chosen_for_steps();
    steps_needed = choice.steps_needed();
  }



  bool
  LinearSolver::switch_after_refactorization(const unsigned int step)
  {
    if (!may_switch || switched)
      return false;
    ++n_refactorizations;
    if (!SolverChoice::refactorizations_outweigh(n_refactorizations,
                                                 step,
                                                 steps_needed))
      return false;
    restore_choice_state(n_refactorizations, true);
    return true;
  }



  std::pair<unsigned int, bool>
  LinearSolver::choice_state() const
  {
    return {n_refactorizations, switched};
  }



  void
  LinearSolver::restore_choice_state(const unsigned int n_refactorizations,
                                     const bool         switched)
  {
    // Not switched: the next choose() takes the method anew (a new cycle
    // of a convergence study is a new run). Switched: the factors go, and
    // initialize() builds the AMG hierarchy.
    this->n_refactorizations = n_refactorizations;
    if (!automatic || switched == this->switched)
      return;
    this->switched = switched;
    if (!switched)
      return;
    clear();
    method = SpdMethod::cg_amg;
    reason += "; CG with AMG after " + std::to_string(n_refactorizations)
              + " factorizations anew for changes of the stick set";
  }



  std::string
  LinearSolver::description() const
  {
    const std::string name = (method == SpdMethod::cg_amg   ? "CG with AMG" :
                              method == SpdMethod::cholesky ? "Cholesky" :
                              method == SpdMethod::mumps    ? "MUMPS" :
                                                              "direct");
    return name + (automatic ? " (automatic: " + reason + ")" : "");
  }



  void
  LinearSolver::initialize_in_background(const LA::SparseMatrix &matrix,
                                         const NearNullSpace &near_null_space)
  {
    if (method != SpdMethod::cholesky)
      {
        initialize(matrix, near_null_space);
        return;
      }
    clear();
    solver = create_spd_solver(linear_algebra, method, "Solver/Linear solver");
    this->matrix                  = &matrix;
    changed_since_initialize      = false;
    rows_changed_since_initialize = 0;
    iterations_before = iterations_after = 0;
    // The BLAS gets all cores but the one the caller works on. On the
    // paper scene at 512^2 cells (2 cores, AMD EPYC) the supernodal
    // factorization takes as long with one BLAS thread as with two (4.1 s);
    // beside the caller's setup it takes longer (the two share the memory),
    // but the first solve then waits about 2 s less for it (scripts/bench,
    // "AMG setup or factorization").
    built_on       = &matrix.trilinos_matrix();
    built_nonzeros = matrix.n_nonzero_elements();
    ++n_builds;
    factorizing = std::async(std::launch::async, [this, &matrix]() {
      const BlasThreadLimit all_but_one(
        std::max(MultithreadInfo::n_threads(), 2u) - 1);
      solver->initialize(matrix, NearNullSpace());
    });
  }



  void
  LinearSolver::wait_for_factors()
  {
    if (factorizing.valid())
      factorizing.get();
  }



  void
  LinearSolver::clear()
  {
    // A factorization still running in the background reads the matrix:
    // wait for it to end. Its factors go, and so does an error it met: the
    // matrix is about to be replaced or destroyed (and a destructor, which
    // calls this, must not throw).
    if (factorizing.valid())
      {
        factorizing.wait();
        factorizing = std::future<void>();
      }
    solver.reset();
    matrix                        = nullptr;
    null_space                    = nullptr;
    changed_since_initialize      = false;
    rows_changed_since_initialize = 0;
  }



  void
  LinearSolver::initialize(const LA::SparseMatrix &matrix,
                           const NearNullSpace    &near_null_space)
  {
    if (!update_values(matrix, near_null_space))
      build(matrix, near_null_space);
  }



  void
  LinearSolver::build(const LA::SparseMatrix &matrix,
                      const NearNullSpace    &near_null_space)
  {
    clear();
    solver = create_spd_solver(linear_algebra, method, "Solver/Linear solver");
    solver->initialize(matrix, near_null_space);
    // AMG's rigid motions, for a rebuild after the matrix changed in place.
    if (method == SpdMethod::cg_amg)
      null_space = &near_null_space;
    this->matrix                  = &matrix;
    built_on                      = &matrix.trilinos_matrix();
    built_nonzeros                = matrix.n_nonzero_elements();
    changed_since_initialize      = false;
    rows_changed_since_initialize = 0;
    iterations_before = iterations_after = 0;
    ++n_builds;
  }



  bool
  LinearSolver::update_values(const LA::SparseMatrix &matrix,
                              const NearNullSpace    &near_null_space)
  {
    // A stick set that changes reassembles the matrix into its pattern and
    // initializes the solver again; so does every Newton step of the
    // implicit scheme. What the pattern alone decides need not be computed
    // again. A solver built for another matrix, or for another pattern of
    // this one, is built anew.
    wait_for_factors();
    if (solver == nullptr || this->matrix != &matrix
        || built_on != &matrix.trilinos_matrix()
        || built_nonzeros != matrix.n_nonzero_elements()
        || (method == SpdMethod::cg_amg && null_space != &near_null_space)
        || !solver->update_values())
      return false;
    changed_since_initialize      = false;
    rows_changed_since_initialize = 0;
    iterations_before = iterations_after = 0;
    ++n_updates;
    return true;
  }



  void
  LinearSolver::rebuild()
  {
    // initialize() keeps a pointer to its near null space, so it must get
    // the caller's object again, not a temporary copy of it: both
    // operands below are lvalues, and the conditional copies neither.
    static const NearNullSpace no_modes;
    const NearNullSpace *const modes = null_space;
    initialize(*matrix, modes ? *modes : no_modes);
  }



  void
  LinearSolver::matrix_changed()
  {
    changed_since_initialize = true;
    if (solver)
      solver->values_changed();
  }



  void
  LinearSolver::rows_changed(const unsigned int changed_rows)
  {
    matrix_changed();
    rows_changed_since_initialize += changed_rows;
  }



  unsigned int
  LinearSolver::rebuild_threshold() const
  {
    // A factorization solves in one step, AMG in its own count; a few more
    // CG iterations are cheaper than a new factorization or hierarchy.
    return std::max(2 * iterations_before, 10u);
  }



  bool
  LinearSolver::preconditioner_outdated() const
  {
    return changed_since_initialize && iterations_after > rebuild_threshold();
  }



  bool
  LinearSolver::keeps_through(const unsigned int changed_rows) const
  {
    // iterations_before is the same on every rank, and so is the count of
    // changed rows (summed over the ranks by the caller): all ranks decide
    // alike.
    if (solver == nullptr || factorizing.valid())
      return false;
    const unsigned int rank
      = 2 * (rows_changed_since_initialize + changed_rows);
    return std::max(iterations_before, 1u) + rank <= rebuild_threshold();
  }



  bool
  LinearSolver::solve_changed_matrix(LA::MPI::Vector       &x,
                                     const LA::MPI::Vector &b,
                                     const double           tolerance,
                                     unsigned int          &iterations)
  {
    // The preconditioner or the factors of the matrix as it was, applied by
    // the SpdSolver of either package to Trilinos vectors.
    struct Preconditioner
    {
      SpdSolver *solver;
      void
      vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const
      {
        solver->precondition(dst, src);
      }
    };
    // Beyond a few times the iterations of a fresh solve, a new
    // preconditioner is cheaper; where the change is large (a slip node's
    // stiffness far above the elastic one) the old one may not converge
    // at all.
    SolverControl         control(std::min(max_iterations,
                                   std::max(4 * iterations_before, 50u)),
                          tolerance);
    const LA::MPI::Vector start(x);
    try
      {
        SolverCG<LA::MPI::Vector> cg(control);
        cg.solve(*matrix, x, b, Preconditioner{solver.get()});
        iterations = iterations_after = control.last_step();
        return true;
      }
    catch (const SolverControl::NoConvergence &)
      {
        x          = start;
        iterations = control.last_step();
        return false;
      }
  }



  double
  LinearSolver::checked_norm(const LA::MPI::Vector &b)
  {
    AssertThrow(all_finite(b, b.get_mpi_communicator()),
                ExcMessage("The right-hand side of the displacement system "
                           "is not finite (NaN or Inf). Check the load "
                           "expressions in 'Boundary conditions'."));
    return b.l2_norm();
  }



  unsigned int
  LinearSolver::solve(LA::MPI::Vector &x, const LA::MPI::Vector &b)
  {
    wait_for_factors();
    const double b_norm = checked_norm(b);
    if (b_norm == 0.)
      {
        x = 0.;
        return 0;
      }
    SolverControl control(
      max_iterations,
      (loose ? std::sqrt(relative_tolerance) : relative_tolerance) * b_norm);
    try
      {
        unsigned int stale_iterations = 0;
        if (changed_since_initialize)
          {
            if (solve_changed_matrix(x,
                                     b,
                                     control.tolerance(),
                                     stale_iterations))
              return stale_iterations;
            rebuild();
          }
        iterations_before = solver->solve(x, b, control);
        return stale_iterations + iterations_before;
      }
    catch (const SolverControl::NoConvergence &e)
      {
        AssertThrow(
          false,
          ExcMessage("CG did not converge: after " + std::to_string(e.last_step)
                     + " iterations the residual is " + to_text(e.last_residual)
                     + " > " + to_text(control.tolerance())
                     + " (Solver/Relative tolerance = "
                     + to_text(relative_tolerance)
                     + " times |b|). Raise Solver/Maximum linear iterations = "
                     + std::to_string(max_iterations)
                     + ", loosen the tolerance, or use Solver/Linear solver = "
                       "direct on small meshes."));
      }
    return 0;
  }



  bool
  LinearSolver::solves_in_background() const
  {
    return method == SpdMethod::cholesky && solver != nullptr
           && !changed_since_initialize;
  }



  std::future<unsigned int>
  LinearSolver::solve_in_background(LA::MPI::Vector             &x,
                                    const LA::MPI::Vector       &b,
                                    const std::function<void()> &then)
  {
    Assert(solves_in_background(), ExcInternalError());
    wait_for_factors();
    // What solve() does with a factorization, in the same order: the checks
    // and the norm (reductions over the ranks) here, in the calling thread;
    // the substitutions in the second thread, which touches nothing but the
    // factors, x and b, and the count of the last solve, read again only
    // after get(). Should the caller leave by an exception before get(),
    // the future's destructor waits for the thread.
    const double b_norm = checked_norm(b);
    if (b_norm == 0.)
      {
        x = 0.;
        return std::async(std::launch::async, [then]() {
          if (then)
            then();
          return 0u;
        });
      }
    const double tolerance = relative_tolerance * b_norm;
    return std::async(std::launch::async, [this, &x, &b, tolerance, then]() {
      SolverControl control(max_iterations, tolerance);
      iterations_before = solver->solve(x, b, control);
      if (then)
        then();
      return iterations_before;
    });
  }



  void
  LinearSolver::precondition(LA::MPI::Vector &dst, const LA::MPI::Vector &src)
  {
    wait_for_factors();
    solver->precondition(dst, src);
  }



  LinearAlgebra
  LinearSolver::package() const
  {
    return linear_algebra;
  }



  bool
  LinearSolver::is_direct() const
  {
    return method != SpdMethod::cg_amg;
  }



  double
  LinearSolver::tolerance() const
  {
    return relative_tolerance;
  }



  void
  LinearSolver::set_loose_tolerance(const bool loose_tolerance)
  {
    loose = loose_tolerance;
  }



  unsigned int
  LinearSolver::iteration_limit() const
  {
    return max_iterations;
  }
} // namespace VPContact
