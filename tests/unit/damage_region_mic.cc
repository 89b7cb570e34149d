// Unit test: the modified incomplete Cholesky factorization MIC(0) of
// DamageRegionSolver keeps the row sums of the matrix, L L^T 1 = K 1. On
// K = M_L/k + kappa A for Q1 elements on an 8 x 8 grid of squares (an
// M-matrix with non-negative row sums), the right-hand side b = K 1 is then
// solved by the first CG iteration: the preconditioned residual of the zero
// start vector is 1 itself, and its step length is 1. IC(0), which drops
// its fill-in instead, needs more. Both converge to x = 1.
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
  const MPI_Comm                   comm = MPI_COMM_SELF;

  // The Q1 damage matrix of an 8 x 8 grid (see q1_damage_matrix()).
  const unsigned int n = 8, nodes = (n + 1) * (n + 1);
  const double       kappa = 0.01, k = 0.01;
  const DenseMatrix  K = q1_damage_matrix(n, kappa, k);

  IndexSet         all = complete_index_set(nodes);
  const RegionRows region(K, all, comm);

  for (const auto kind :
       {DamageRegionSolver::Preconditioner::modified_incomplete_cholesky,
        DamageRegionSolver::Preconditioner::incomplete_cholesky,
        DamageRegionSolver::Preconditioner::diagonal})
    {
      DamageRegionSolver solver;
      solver.initialize(region.rows, kind);
      solver.begin_step();
      LA::MPI::Vector b(all, comm), x(all, comm);
      for (unsigned int i = 0; i < nodes; ++i)
        {
          double s = 0;
          for (unsigned int j = 0; j < nodes; ++j)
            s += K[i][j];
          b(i) = s;
        }
      const unsigned int iterations = solver.solve(b, x, {}, 1e-12, 100);
      double             error      = 0;
      for (unsigned int i = 0; i < nodes; ++i)
        error = std::max(error, std::abs(x(i) - 1.));
      std::cout << name(kind)
                << ": |x - 1| below 1e-10: " << (error < 1e-10 ? "yes" : "no")
                << ", CG iterations: "
                << (iterations == 1 ? "1" :
                    iterations > 1  ? "more than 1" :
                                      "0")
                << std::endl;
    }
}
