// The section "Solver" and the solution of the displacement system.
#include <vpcontact/finite_values.h>
#include <vpcontact/input_error.h>
#include <vpcontact/linear_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

namespace VPContact
{
  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      prm.declare_entry("Linear solver",
                        "CG with AMG",
                        Patterns::Selection(
                          "CG with AMG|direct|MUMPS|Cholesky"),
                        "'CG with AMG': conjugate gradients preconditioned by "
                        "Trilinos ML algebraic multigrid, scales to large "
                        "meshes and many ranks. 'direct': Trilinos Amesos KLU "
                        "factorization, exact to round-off, for small meshes "
                        "(it gathers the matrix). 'MUMPS': the multifrontal "
                        "MUMPS factorization through Amesos (distributed), "
                        "for medium meshes where one factorization per "
                        "matrix, reused by every step, beats CG. 'Cholesky': "
                        "the supernodal sparse Cholesky factorization of "
                        "SuiteSparse CHOLMOD, serial runs only, the fastest "
                        "factorization on one process; see "
                        "doc/performance.md. Direct factorizations are "
                        "recomputed whenever the stick set changes.");
      prm.declare_entry(
        "Second thread",
        "true",
        Patterns::Bool(),
        "Where each rank has a second core to itself (one process on two "
        "cores or more): the passes over the cells in every step work on "
        "two halves of the cells at once, and with Linear solver = "
        "Cholesky the solve with the factors runs beside the damage step, "
        "or, where nothing runs beside it, in two threads (on two "
        "independent parts of the factors), and the factorization uses two "
        "BLAS threads (with a threaded OpenBLAS). The results are the same bits either way, but for the "
        "factorization in two threads, which rounds differently (the "
        "figures printed are the same; each setting gives the same bits "
        "from run to run). Under mpirun each rank is bound to one core by "
        "default, and this changes nothing.");
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
    const std::string method = prm.get("Linear solver");
    solver_method            = (method == "CG with AMG" ? Method::cg_amg :
                                method == "Cholesky"    ? Method::cholesky :
                                                          Method::direct);
    direct_package       = (method == "MUMPS" ? "Amesos_Mumps" : "Amesos_Klu");
    relative_tolerance   = prm.get_double("Relative tolerance");
    max_iterations       = prm.get_integer("Maximum linear iterations");
    second_thread_wanted = prm.get_bool("Second thread");
    prm.leave_subsection();
    // At 1 the start vector already meets the tolerance, and no step would
    // be solved at all.
    VPContactCheckParameter(relative_tolerance > 0 && relative_tolerance < 1,
                            "Solver/Relative tolerance",
                            relative_tolerance,
                            "must lie in (0, 1), e.g. 1e-10.");
    // CHOLMOD factorizes on one process; under mpirun the matrix is split
    // over the ranks, and MUMPS is the distributed factorization.
    VPContactCheckParameter(solver_method != Method::cholesky
                              || Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
                                   == 1,
                            "Solver/Linear solver",
                            method,
                            "factorizes on one process only: run without "
                            "mpirun, or choose MUMPS "
                            "(distributed) or CG with AMG.");
  }



  void
  LinearSolver::clear()
  {
    cholesky.reset();
    direct.reset();
    direct_control.reset();
    amg.reset();
  }



  void
  LinearSolver::initialize(const TrilinosWrappers::SparseMatrix &matrix,
                           const std::vector<std::vector<bool>> &constant_modes)
  {
    clear();
    if (solver_method == Method::cg_amg)
      {
        // The settings of step-42 for elasticity: a symmetric problem
        // (elliptic = true), the rigid translations as near null space,
        // aggressive smoothing on few levels.
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 1e-2;
        data.constant_modes        = constant_modes;
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(matrix, data);
      }
    else if (solver_method == Method::cholesky)
      {
        cholesky = std::make_unique<SparseCholesky>();
        cholesky->factorize(matrix, second_thread ? 2 : 1);
      }
    else
      {
        direct_control = std::make_unique<SolverControl>(1, 0);
        direct         = std::make_unique<TrilinosWrappers::SolverDirect>(
          *direct_control,
          TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                         direct_package));
        direct->initialize(matrix);
      }
  }



  unsigned int
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector        &x,
                      const TrilinosWrappers::MPI::Vector  &b)
  {
    const double b_norm = checked_norm(b);
    if (b_norm == 0.)
      {
        x = 0.;
        return 0;
      }

    if (solver_method == Method::direct)
      {
        direct->solve(x, b);
        return 1;
      }
    if (solver_method == Method::cholesky)
      {
        // Nothing runs beside this solve: with a second core the
        // substitutions use it (see SparseCholesky::solve()).
        cholesky->solve(x, b, second_thread ? 2 : 1);
        return 1;
      }

    SolverControl control(max_iterations, relative_tolerance * b_norm);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(matrix, x, b, *amg);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        AssertThrow(
          false,
          ExcMessage(
            "CG did not converge: after " + std::to_string(e.last_step)
            + " iterations the "
              "residual is "
            + to_text(e.last_residual) + " > " + to_text(control.tolerance())
            + " (Solver/Relative tolerance = " + to_text(relative_tolerance)
            + " times |b|). Raise "
              "Solver/Maximum linear iterations = "
            + std::to_string(max_iterations)
            + ", loosen the tolerance, or use Solver/Linear solver = "
              "direct on small meshes."));
      }
    return control.last_step();
  }



  double
  LinearSolver::checked_norm(const TrilinosWrappers::MPI::Vector &b)
  {
    AssertThrow(all_finite(b, b.get_mpi_communicator()),
                ExcMessage("The right-hand side of the displacement system "
                           "is not finite (NaN or Inf). Check the load "
                           "expressions in 'Boundary conditions'."));
    return b.l2_norm();
  }



  void
  LinearSolver::set_cores_per_rank(const unsigned int cores)
  {
    second_thread = second_thread_wanted && cores >= 2;
  }



  bool
  LinearSolver::uses_second_thread() const
  {
    return second_thread;
  }



  bool
  LinearSolver::solves_in_background() const
  {
    return second_thread && solver_method == Method::cholesky;
  }



  std::future<unsigned int>
  LinearSolver::solve_in_background(TrilinosWrappers::MPI::Vector       &x,
                                    const TrilinosWrappers::MPI::Vector &b,
                                    const std::function<void()>         &then)
  {
    Assert(solves_in_background(), ExcInternalError());
    // The norm is a reduction over the ranks: taken here, in the calling
    // thread. Exceptions of the second thread reach the caller from get();
    // should the caller leave by an exception first, the future's
    // destructor waits for the thread.
    const bool zero = (checked_norm(b) == 0.);
    if (zero)
      x = 0.;
    if (zero && !then)
      {
        std::promise<unsigned int> done;
        done.set_value(0);
        return done.get_future();
      }
    return std::async(std::launch::async, [this, &x, &b, zero, then]() {
      if (!zero)
        cholesky->solve(x, b);
      if (then)
        then();
      return zero ? 0u : 1u;
    });
  }



  void
  LinearSolver::precondition(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src) const
  {
    if (solver_method == Method::cg_amg)
      amg->vmult(dst, src);
    else if (solver_method == Method::cholesky)
      cholesky->solve(dst, src);
    else
      direct->solve(dst, src);
  }



  LinearSolver::Method
  LinearSolver::method() const
  {
    return solver_method;
  }



  double
  LinearSolver::tolerance() const
  {
    return relative_tolerance;
  }



  unsigned int
  LinearSolver::iteration_limit() const
  {
    return max_iterations;
  }
} // namespace VPContact
