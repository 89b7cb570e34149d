// Unit test: the cut between the ranks in DamageRegionSolver's
// preconditioners. On K = M_L/k + kappa A for Q1 elements on a 32 x 32 grid
// with kappa k / h^2 = 10.24 (the diffusion dominates, as on fine meshes),
// the left quarter held at 0, b = K x* for a known x*, the rows split into
// contiguous halves (a horizontal cut through the free nodes): every
// preconditioner must give x* back, and the CG iterations are printed. The
// diagonal variant and MIC(0) take half of the cut rows' entries in the
// other rank's columns into their diagonal; without that (plain block
// Jacobi) both need more iterations here, so the count changes and the
// test fails.
#include <vpcontact/damage/damage_region_solver.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iostream>

#include "damage_region_test_tools.h"

using namespace VPContact;
using namespace VPContact::DamageRegionTestTools;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);

  // The model problem of 32 x 32 cells with the left quarter held (see
  // HeldQuarterProblem), its rows split into contiguous halves.
  const HeldQuarterProblem problem(32, 0.01, 1., comm);

  for (const auto kind :
       {DamageRegionSolver::Preconditioner::modified_incomplete_cholesky,
        DamageRegionSolver::Preconditioner::diagonal})
    {
      DamageRegionSolver solver;
      solver.initialize(problem.region.rows, kind);
      solver.begin_step();
      LA::MPI::Vector           b, x(problem.owned, comm);
      std::vector<unsigned int> held_positions;
      problem.right_hand_side(b, held_positions);
      const unsigned int iterations
        = solver.solve(b, x, held_positions, 1e-12, 500);
      const double error = problem.error(x);
      if (rank == 0)
        std::cout << name(kind)
                  << ": |x - x*| below 1e-9: " << (error < 1e-9 ? "yes" : "no")
                  << ", CG iterations: " << iterations << std::endl;
    }
}
