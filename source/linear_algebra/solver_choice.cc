// What Solver/Linear solver = automatic takes for the displacement system:
// the limits and the fitted break-even step counts behind the choice.
#include <vpcontact/linear_algebra/solver_choice.h>

#include <cmath>

namespace VPContact
{
  namespace
  {
    // Below this size a factorization builds in under half a second
    // (0.45 s for the 14,739 unknowns of the 3D paper scene on 16^3 cells,
    // the slowest case measured), so it is taken whatever the steps: with
    // either solver such a run takes about as long, and the factors solve
    // exactly.
    constexpr types::global_dof_index always_factorized = 20000;

    // On several processes in 2D, CG with AMG is the faster both to build
    // and per step below about 100,000 unknowns (scripts/bench_solvers, 2
    // ranks: 128^2 cells, 33,282 unknowns, 0.08 s + 20.8 ms per step
    // against MUMPS' 0.31 s + 25.2 ms), so it is taken there whatever the
    // steps.
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
    // The factors grow like n log n in 2D and like n^(4/3) in 3D. The run
    // of the 2D paper scene on 512^2 cells (526,338 unknowns) took 1.7 GB
    // with the factors and 1.3 GB with AMG: four times the unknowns stay
    // within a machine's memory. In 3D the limit is the largest size
    // measured, 206,763 unknowns (40^3 cells), whose factors took 32 s to
    // build.
    return dim == 2 ? 2000000 : 210000;
  }



  double
  SolverChoice::break_even_steps(const types::global_dof_index n_unknowns,
                                 const unsigned int            dim,
                                 const unsigned int            n_ranks)
  {
    // S*(n) = S*(10^5) (n / 10^5)^p, fitted by least squares in log-log
    // (scripts/bench_solvers_report.py, the run of commit fb85cda, AMD
    // EPYC, ten steps) to the cases without slip where the factorization's
    // step is clearly the cheaper (Cholesky on 1 rank, MUMPS on 2, against
    // CG with AMG):
    // - 2D, 1 process: 7 steps at 132,098 unknowns, 8 at 526,338 (the paper
    //   scene), S*(10^5) = 7.15, p = 0.07;
    // - 2D, several processes: 21 and 49 there, 17.5 and 0.62;
    // - 3D, 1 process: 8 at 14,739 to 65 at 206,763 (the paper scene, 16^3
    //   to 40^3 cells), 11 to 122 on the blocks with a hole (4,170 to
    //   204,816), 45.8 and 0.60;
    // - 3D, several processes: 24 at 14,739 to 278 at 206,763, 148 and
    //   0.93.
    // Measured on 2 ranks: on more, CG with AMG gains more from them than
    // MUMPS does, so these counts are lower bounds there.
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
    // On the slip scene of 512^2 cells the stick set changes about three
    // times a step, and each Cholesky factorization anew costs about 1.5 s
    // against 0.65 s for an AMG hierarchy (scripts/bench_solvers: 47.9 s
    // of builds over ten steps against 20 s): CG with AMG took 6.3 s a step
    // where Cholesky took 8.2 s. The paper scene on 512^2 cells keeps its
    // factorization through its 100 steps.
    constexpr double margin = 2;
    return n_refactorizations > margin + step / steps_needed;
  }
} // namespace VPContact
