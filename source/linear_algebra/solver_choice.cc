// What Solver/Linear solver = automatic takes for the displacement system:
// the limits and the fitted break-even step counts behind the choice.
#include <vpcontact/linear_algebra/solver_choice.h>

#include <cmath>

namespace VPContact
{
  namespace
  {
    // Below this size a factorization builds in a fraction of a second in
    // every case scripts/bench_solvers measures, so it is taken whatever
    // the steps: with either solver such a run takes about as long, and
    // the factors solve exactly.
    constexpr types::global_dof_index always_factorized = 20000;

    // On several processes in 2D, CG with AMG is the faster both to build
    // and per step below about this size (the 2-rank columns of
    // doc/performance.md, "Which solver the automatic choice takes"), so
    // it is taken there whatever the steps.
    constexpr types::global_dof_index least_distributed_2d = 100000;

    std::string
    to_text(const double steps)
    {
      return std::to_string(static_cast<unsigned long>(std::ceil(steps)));
    }
  } // namespace



  types::global_dof_index
  SolverChoice::factorization_limit(const unsigned int dim)
  {
    // The factors grow like n log n in 2D and like n^(4/3) in 3D. In 2D
    // the limit is about four times the largest size scripts/bench_solvers
    // measures (the paper scene on 512^2 cells), whose run with the
    // factors stays well within a machine's memory. In 3D it is the
    // largest size measured: beyond it the fit of break_even_steps() has
    // no data, and the factors' memory grows fastest there.
    return dim == 2 ? 2000000 : 210000;
  }



  double
  SolverChoice::break_even_steps(const types::global_dof_index n_unknowns,
                                 const unsigned int            dim,
                                 const unsigned int            n_ranks)
  {
    // S*(n) = S*(10^5) (n / 10^5)^p: the least-squares fit in log-log that
    // scripts/bench_solvers_report.py writes into doc/performance.md
    // ("Which solver the automatic choice takes", with the measured S* of
    // every case), over the cases without slip where the factorization's
    // step is clearly the cheaper (Cholesky on 1 rank, MUMPS on 2, against
    // CG with AMG). The constants below are that fit; when the solvers
    // change, measure again and copy the page's fit here. Measured on 2
    // ranks: on more, CG with AMG gains more from them than MUMPS does, so
    // these counts are lower bounds there.
    const bool   several = (n_ranks > 1);
    const double at_1e5
      = (dim == 2 ? (several ? 17.5 : 7.15) : (several ? 148. : 45.8));
    const double power
      = (dim == 2 ? (several ? 0.62 : 0.07) : (several ? 0.93 : 0.60));
    return at_1e5 * std::pow(static_cast<double>(n_unknowns) / 1e5, power);
  }



  SolverChoice::SolverChoice(const types::global_dof_index n_unknowns,
                             const unsigned int            dim,
                             const unsigned int            n_ranks,
                             const unsigned int            n_steps)
  {
    const std::string size
      = std::to_string(n_unknowns) + " displacement unknowns in "
        + std::to_string(dim) + "D on " + std::to_string(n_ranks)
        + (n_ranks == 1 ? " process" : " processes");
    const types::global_dof_index limit = factorization_limit(dim);
    needed         = break_even_steps(n_unknowns, dim, n_ranks);
    bool factorize = false;
    if (n_unknowns > limit)
      why = size + ", more than the " + std::to_string(limit)
            + " whose factors fit in memory";
    else if (n_ranks > 1 && dim == 2 && n_unknowns < least_distributed_2d)
      why = size + ", fewer than the " + std::to_string(least_distributed_2d)
            + " from which a distributed factorization is the faster";
    else if (n_unknowns < always_factorized)
      {
        factorize = true;
        why       = size + ", fewer than " + std::to_string(always_factorized);
      }
    else
      {
        factorize = (n_steps >= needed);
        for_steps = factorize;
        why       = size + ", " + std::to_string(n_steps)
              + " steps: a factorization is the faster from " + to_text(needed)
              + " steps on";
      }
    chosen = (!factorize   ? SpdMethod::cg_amg :
              n_ranks == 1 ? SpdMethod::cholesky :
                             SpdMethod::mumps);
  }



  SpdMethod
  SolverChoice::method() const
  {
    return chosen;
  }



  const std::string &
  SolverChoice::reason() const
  {
    return why;
  }



  bool
  SolverChoice::chosen_for_steps() const
  {
    return for_steps;
  }



  double
  SolverChoice::steps_needed() const
  {
    return needed;
  }



  bool
  SolverChoice::refactorizations_outweigh(const unsigned int n_refactorizations,
                                          const unsigned int step,
                                          const double       steps_needed)
  {
    // Where the contact face slips, the stick set changes several times a
    // step, and each change builds the factorization anew, at a few times
    // the cost of an AMG hierarchy (the build column of doc/performance.md,
    // "Which solver the automatic choice takes"): there CG with AMG is the
    // faster. A run whose stick set settles, as the paper scene's, keeps
    // its factorization, and a few changes early in a run (the margin) do
    // not switch it.
    constexpr double margin = 2;
    return n_refactorizations > margin + step / steps_needed;
  }
} // namespace VPContact
