// Unit test: DamageRegionSolver with its rows split over the ranks. On
// K = M_L/k + kappa A for Q1 elements on a 16 x 16 grid of squares, with
// the nodes of the left quarter held at 0, b = K x* for a known x* that
// vanishes there; every preconditioner must give x* back. The rows are
// split into contiguous halves (a horizontal cut through the free nodes),
// so on 2 ranks the product reads the other rank's entries and the
// preconditioners are block Jacobi between the ranks. For the diagonal
// preconditioner, whose CG runs on the transformed system, the coupling to
// the other rank is a term of its own (K_off in solve_eisenstat()): with it
// left out, this test fails on 2 ranks.
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

  // The model problem of 16 x 16 cells with the left quarter held (see
  // HeldQuarterProblem), its rows split into contiguous halves.
  const HeldQuarterProblem problem(16, 0.01, 0.01, comm);

  for (const auto kind :
       {DamageRegionSolver::Preconditioner::incomplete_cholesky,
        DamageRegionSolver::Preconditioner::modified_incomplete_cholesky,
        DamageRegionSolver::Preconditioner::diagonal})
    {
      DamageRegionSolver solver;
      solver.initialize(problem.region.rows, kind);
      solver.begin_step();
      LA::MPI::Vector           b, x(problem.owned, comm);
      std::vector<unsigned int> held_positions;
      problem.right_hand_side(b, held_positions);
      solver.solve(b, x, held_positions, 1e-12, 200);
      const double error = problem.error(x);
      bool         zero  = true;
      for (const auto i : problem.owned)
        zero = zero && (!problem.held[i] || x(i) == 0.);
      zero = (Utilities::MPI::min(zero ? 1 : 0, comm) == 1);
      if (rank == 0)
        std::cout << name(kind)
                  << ": |x - x*| below 1e-9: " << (error < 1e-9 ? "yes" : "no")
                  << ", held nodes exactly 0: " << (zero ? "yes" : "no")
                  << std::endl;
    }
}
