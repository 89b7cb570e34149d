// Unit test: what Solver/Linear solver = automatic takes (SolverChoice).
// Each case names the measured builds and steps of scripts/bench_solvers
// (AMD EPYC, the table "Which solver the automatic choice takes" of
// doc/performance.md) to compare its choice with, so a change of the
// fitted break-even counts that turns one of them shows here:
// - the factors' memory: no factorization beyond 2,000,000 unknowns in 2D
//   and 210,000 in 3D;
// - below 20,000 unknowns a factorization whatever the steps, but never on
//   several processes in 2D below 100,000;
// - in between a factorization from the break-even number of steps on;
// - a run that factorizes anew for changes of the stick set more often
//   than once per break-even count of steps (after a margin of two)
//   switches to CG with AMG, keeps it on a new mesh, and a checkpoint's
//   state restores the switch.
#include <vpcontact/linear_algebra/linear_solver.h>
#include <vpcontact/linear_algebra/solver_choice.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cstdio>

using namespace VPContact;

void
show(const types::global_dof_index n,
     const unsigned int            dim,
     const unsigned int            ranks,
     const unsigned int            steps,
     const char                   *measured)
{
  const SolverChoice choice(n, dim, ranks, steps);
  const SpdMethod    m = choice.method();
  std::printf("%s (%s)\n  measured: %s\n",
              m == SpdMethod::cholesky ? "Cholesky" :
              m == SpdMethod::mumps    ? "MUMPS" :
              m == SpdMethod::cg_amg   ? "CG with AMG" :
                                         "other",
              choice.reason().c_str(),
              measured);
}

void
show_switch()
{
  ParameterHandler prm;
  LinearSolver::declare_parameters(prm);
  LinearSolver solver;
  solver.parse_parameters(prm);
  // The slip scene on 128^2 cells: 33,282 unknowns, 10 steps.
  solver.choose(33282, 2, 1, 10);
  std::printf("slip scene 128^2, 10 steps: %s\n", solver.description().c_str());
  for (const unsigned int step : {1u, 1u, 1u})
    {
      const bool switched = solver.switch_after_refactorization(step);
      std::printf("  factorization anew at step %u: %s\n",
                  step,
                  switched ? "switched" : "kept");
    }
  std::printf("  now: %s\n", solver.description().c_str());
  solver.choose(132098, 2, 1, 10);
  std::printf("  on a new mesh: %s\n", solver.description().c_str());
  const auto [n, switched] = solver.choice_state();

  LinearSolver resumed;
  resumed.parse_parameters(prm);
  resumed.choose(33282, 2, 1, 10);
  resumed.restore_choice_state(n, switched);
  std::printf("resumed from (%u, %s): %s\n",
              n,
              switched ? "switched" : "not switched",
              resumed.description().c_str());
  resumed.restore_choice_state(0, false);
  resumed.choose(33282, 2, 1, 10);
  std::printf("a new cycle: %s\n", resumed.description().c_str());

  // The paper scene on 512^2 cells over 100 steps: a change now and then
  // keeps the factorization.
  LinearSolver paper;
  paper.parse_parameters(prm);
  paper.choose(526338, 2, 1, 100);
  unsigned int kept = 0;
  for (const unsigned int step : {1u, 1u, 20u, 40u, 60u, 80u, 100u})
    kept += !paper.switch_after_refactorization(step);
  std::printf("paper scene 512^2, 7 factorizations anew over 100 steps: %u "
              "kept: %s\n",
              kept,
              paper.description().c_str());
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::printf("break-even steps at 10^5 and 10^6 unknowns:\n");
  for (const unsigned int dim : {2u, 3u})
    for (const unsigned int ranks : {1u, 2u})
      std::printf("  %uD, %u rank(s): %.1f, %.1f\n",
                  dim,
                  ranks,
                  SolverChoice::break_even_steps(100000, dim, ranks),
                  SolverChoice::break_even_steps(1000000, dim, ranks));

  show(526338,
       2,
       1,
       100,
       "Cholesky 5.26 s + 100 x 257 ms, AMG 2.2 s + 100 x 640 ms");
  show(526338, 2, 1, 5, "Cholesky 5.26 s + 5 x 257 ms, AMG 2.2 s + 5 x 640 ms");
  show(206763,
       3,
       1,
       10,
       "Cholesky 32.1 s + 10 x 458 ms, AMG 3.0 s + 10 x 908 ms");
  show(206763,
       3,
       1,
       100,
       "Cholesky 32.1 s + 100 x 458 ms, AMG 3.0 s + 100 x 908 ms");
  show(204816,
       3,
       1,
       100,
       "block with hole: Cholesky 18 s + 100 x 454 ms, AMG 3.76 s + 100 x "
       "571 ms (AMG 4 % the faster: its S* is 122, the fit 70)");
  show(14739,
       3,
       1,
       2,
       "Cholesky 0.45 s + 2 x 29.9 ms, AMG 0.24 s + 2 x 57.1 ms");
  show(526338,
       2,
       2,
       100,
       "MUMPS 4.79 s + 100 x 244 ms, AMG 1.14 s + 100 x 318 ms");
  show(132098,
       2,
       2,
       10,
       "MUMPS 1.22 s + 10 x 83.1 ms, AMG 0.39 s + 10 x 123 ms");
  show(33282,
       2,
       2,
       100,
       "MUMPS 0.31 s + 100 x 25.2 ms, AMG 0.08 s + 100 x 20.8 ms");
  show(206763,
       3,
       2,
       100,
       "MUMPS 42 s + 100 x 575 ms, AMG 2.82 s + 100 x 716 ms");
  show(3000000, 2, 1, 1000, "beyond the 2D limit");
  show(300000, 3, 1, 1000, "beyond the 3D limit");

  show_switch();
}
