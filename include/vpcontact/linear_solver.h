// The linear solver of the displacement system: AMG-preconditioned CG or a
// direct factorization, built once per matrix and reused at every step.
#ifndef vpcontact_linear_solver_h
#define vpcontact_linear_solver_h

#include <vpcontact/sparse_cholesky.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <future>
#include <memory>
#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Solver": solves K x = b for a symmetric positive definite K.
   *
   * The matrix of the paper's velocity problem is constant while the mesh
   * and the time step are fixed, so the preconditioner (or the factorization)
   * is built once in initialize() and reused by every solve().
   */
  class LinearSolver
  {
  public:
    enum class Method
    {
      cg_amg,
      direct,
      cholesky
    };

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Build the preconditioner or factorization of @p matrix. The
     * @p constant_modes (one bool vector per displacement component) help
     * AMG to coarsen a vector-valued problem, as in step-42.
     */
    /**
     * Release the preconditioner or factorization. Both refer to the matrix
     * they were built from (MUMPS even when it is destroyed), so this must
     * happen before that matrix is re-initialised or destroyed.
     */
    void
    clear();

    void
    initialize(const TrilinosWrappers::SparseMatrix &matrix,
               const std::vector<std::vector<bool>> &constant_modes);

    /**
     * Solve matrix x = b. @p x is the start vector for CG. Returns the number
     * of iterations (1 for the direct solver, 0 for b = 0). Throws with a
     * message naming the Solver parameters to change when CG does not reach
     * the tolerance.
     */
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &x,
          const TrilinosWrappers::MPI::Vector  &b);

    /// The cores each rank has to itself (see cores_per_rank()): a second
    /// thread needs two.
    void
    set_cores_per_rank(const unsigned int cores);

    /// Solver/Second thread, where each rank has two cores to itself.
    bool
    uses_second_thread() const;

    /// Whether solve_in_background() may be called: a second thread and
    /// the Cholesky factors.
    bool
    solves_in_background() const;

    /**
     * As solve(), with the triangular solves of the Cholesky factors in a
     * second thread; the result is in @p x once get() of the returned
     * future returns. That thread touches nothing but @p x, @p b and the
     * factors, and calls no MPI function (MPI is initialized for one
     * calling thread at a time): until get(), the caller may do anything
     * else, but must leave @p x and @p b alone. @p then, if given, runs in
     * the same thread once @p x is there (also where b = 0 and x = 0
     * without a solve), under the same rules. Only if
     * solves_in_background().
     */
    std::future<unsigned int>
    solve_in_background(TrilinosWrappers::MPI::Vector       &x,
                        const TrilinosWrappers::MPI::Vector &b,
                        const std::function<void()>         &then = {});

    /// One application of the preconditioner (AMG V-cycle) or, for the
    /// direct solvers, one solve with the factors: dst = P^{-1} src.
    void
    precondition(TrilinosWrappers::MPI::Vector       &dst,
                 const TrilinosWrappers::MPI::Vector &src) const;

    Method
    method() const;

    double
    tolerance() const;

    unsigned int
    iteration_limit() const;

  private:
    /// |b|, checked to be finite.
    static double
    checked_norm(const TrilinosWrappers::MPI::Vector &b);

    Method solver_method = Method::cg_amg;
    /// Solver/Second thread, and whether it is used (see
    /// set_cores_per_rank()).
    bool second_thread_wanted = true;
    bool second_thread        = false;
    /// The Amesos package of the direct method: Amesos_Klu or Amesos_Mumps.
    std::string  direct_package     = "Amesos_Klu";
    double       relative_tolerance = 1e-10;
    unsigned int max_iterations     = 1000;

    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    std::unique_ptr<SolverControl>                     direct_control;
    std::unique_ptr<TrilinosWrappers::SolverDirect>    direct;
    /// The serial sparse Cholesky factors (method cholesky).
    std::unique_ptr<SparseCholesky> cholesky;
  };
} // namespace VPContact

#endif
