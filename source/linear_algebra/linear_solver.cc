// The section "Solver" and the solution of the displacement system.
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/blas_threads.h>
#include <vpcontact/linear_algebra/finite_values.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

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
        "'automatic': by the size alone, 'Cholesky' on one process and "
        "'MUMPS' on several up to 2,000,000 displacement unknowns in 2D and "
        "210,000 in 3D (on several ranks in 2D from 100,000 on), else 'CG "
        "with AMG'; the header names the choice. It weighs neither the "
        "run's steps against a factorization's one-time cost nor the "
        "factorizations anew after changes of the stick set: for a short "
        "run in 3D, or a scene whose base slips, 'CG with AMG' is often "
        "the faster (doc/performance.md, scripts/bench_solvers). "
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



  types::global_dof_index
  LinearSolver::factorization_limit(const unsigned int dim,
                                    const unsigned int n_ranks)
  {
    // The limits of a measurement (scripts/bench_solvers at 13ac5d8) that
    // counted the steps' times only, in which a factorization was the
    // faster in every case: 2D up to 526,000 displacement unknowns (512^2),
    // 3D up to 207,000 (40^3, and the block with a hole refined twice).
    // With the factorization's time counted wherever the run spends it,
    // CG with AMG is the faster over ten steps in 3D from 24^3 on, and on
    // scenes whose stick set changes in most steps; a factorization wins
    // beyond a number of steps that grows with the size (65 at 40^3;
    // doc/performance.md splits each run into its builds and its steps).
    // The limits are those sizes in 3D, where the factors grow like
    // n^(4/3), and 2,000,000 in 2D, where they grow like n log n (the run
    // of 512^2 took 1.7 GB with the factors and 1.3 GB with AMG: four times
    // the unknowns stay within a machine's memory).
    (void)n_ranks;
    return dim == 2 ? 2000000 : 210000;
  }



  void
  LinearSolver::choose(const types::global_dof_index n_unknowns,
                       const unsigned int            dim,
                       const unsigned int            n_ranks)
  {
    if (!automatic)
      return;
    // On several ranks, MUMPS' distributed analysis costs more than CG
    // with AMG below about 100,000 unknowns in 2D (scripts/bench_solvers:
    // AMG was the faster on 2 ranks up to 52,704, MUMPS from 132,098).
    const types::global_dof_index limit = factorization_limit(dim, n_ranks);
    const types::global_dof_index least
      = (n_ranks > 1 && dim == 2) ? 100000 : 0;
    const bool factorize = (n_unknowns <= limit && n_unknowns >= least);
    method               = (!factorize   ? SpdMethod::cg_amg :
                            n_ranks == 1 ? SpdMethod::cholesky :
                                           SpdMethod::mumps);
    reason = std::to_string(n_unknowns) + " displacement unknowns in "
             + std::to_string(dim) + "D on " + std::to_string(n_ranks)
             + (n_ranks == 1 ? " process" : " processes") + ", "
             + (factorize ? "within" : "outside") + " [" + std::to_string(least)
             + ", " + std::to_string(limit) + "]";
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
