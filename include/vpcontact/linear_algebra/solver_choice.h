// What Solver/Linear solver = automatic takes for the displacement system: a
// factorization where its factors fit in memory and the run's steps repay
// its one-time cost, else CG with AMG.
#ifndef vpcontact_solver_choice_h
#define vpcontact_solver_choice_h

#include <vpcontact/linear_algebra/spd_solver.h>

#include <deal.II/base/types.h>

#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * The automatic choice of the displacement solver, from the size of the
   * system, the dimension, the number of processes and the number of steps
   * of the run.
   *
   * A factorization costs more to build than an AMG hierarchy and less per
   * solve, so a run of S steps takes about build + S step with either, and
   * the factorization is the faster from
   *   S* = (build_factorization - build_AMG) / (step_AMG - step_factorization)
   * steps on. scripts/bench_solvers measures both splits on 2D and 3D scenes
   * of growing size (doc/performance.md, "Which solver the automatic choice
   * takes"); S* grows with the unknowns n like a power, S*(n) = S*(10^5)
   * (n / 10^5)^p, with S*(10^5) and p fitted per dimension and for one
   * process or several (break_even_steps()).
   *
   * The choice cannot know whether the stick set will change: every change
   * that is not small factorizes anew, and the first build's S* then holds
   * for each new factorization, which must serve S* steps to repay what it
   * costs beyond an AMG hierarchy. A run that factorizes anew more often
   * than that (the base slipping) is better served by CG with AMG, and
   * switches to it for its remaining steps (refactorizations_outweigh()).
   */
  class SolverChoice
  {
  public:
    /// The choice for @p n_unknowns displacement unknowns in @p dim
    /// dimensions on @p n_ranks processes over a run of @p n_steps steps.
    SolverChoice(const types::global_dof_index n_unknowns,
                 const unsigned int            dim,
                 const unsigned int            n_ranks,
                 const unsigned int            n_steps);

    /// Cholesky on one process, MUMPS on several, or CG with AMG.
    SpdMethod
    method() const;

    /// Why, for the header of a run.
    const std::string &
    reason() const;

    /// The largest system the choice factorizes (the factors' memory).
    static types::global_dof_index
    factorization_limit(const unsigned int dim);

    /// The number of steps from which a factorization is the faster.
    static double
    break_even_steps(const types::global_dof_index n_unknowns,
                     const unsigned int            dim,
                     const unsigned int            n_ranks);

    /// Whether the factorization was chosen for the run's steps (not
    /// because the system is small), so that refactorizations may undo it.
    bool
    chosen_for_steps() const;

    /// break_even_steps() of this system.
    double
    steps_needed() const;

    /**
     * Whether @p n_refactorizations factorizations anew after changes of
     * the stick set, up to step @p step, come more often than one per @p
     * steps_needed steps, with a margin of two for the changes of a run's
     * first steps (where the stick set settles from the all-stick start).
     */
    static bool
    refactorizations_outweigh(const unsigned int n_refactorizations,
                              const unsigned int step,
                              const double       steps_needed);

  private:
    SpdMethod   chosen;
    std::string why;
    bool        for_steps = false;
    double      needed    = 0;
  };
} // namespace VPContact

#endif
