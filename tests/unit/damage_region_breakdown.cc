// Unit test: DamageRegionSolver on Kershaw's 4 x 4 SPD matrix, whose
// incomplete Cholesky factorization IC(0) breaks down (the last pivot is
// 3 - 4/3 - 20/3 = -5). The solver must keep the diagonal of the matrix for
// such a pivot, with IC(0) and with its modified form MIC(0) (not meant for
// a matrix with positive entries off the diagonal), so that the
// preconditioner stays SPD and CG converges to the known solution x* = (1, 2,
// 3, 4), with no node held and with node 1 held (then x_1 = 0 and the others
// solve the 3 x 3 system of the free nodes); and for b = 0 it returns x = 0
// without iterations.
#include <vpcontact/damage/damage_region_solver.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

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

  const DenseMatrix kershaw
    = {{3, -2, 0, 2}, {-2, 3, -2, 0}, {0, -2, 3, -2}, {2, 0, -2, 3}};
  IndexSet         all = complete_index_set(4);
  const RegionRows region(kershaw, all, comm);

  for (const auto kind :
       {DamageRegionSolver::Preconditioner::incomplete_cholesky,
        DamageRegionSolver::Preconditioner::modified_incomplete_cholesky,
        DamageRegionSolver::Preconditioner::diagonal})
    {
      DamageRegionSolver solver;
      solver.initialize(region.rows, kind);
      solver.begin_step();

      for (const bool hold_node_1 : {false, true})
        {
          // x*: (1, 2, 3, 4), or with x_1 = 0 and the free rows of b from the
          // 3 x 3 system.
          Vector<double> exact({1., 2., 3., 4.});
          if (hold_node_1)
            exact(1) = 0.;
          std::vector<unsigned int> held;
          if (hold_node_1)
            held.push_back(1);
          LA::MPI::Vector b(all, comm), x(all, comm);
          for (unsigned int i = 0; i < 4; ++i)
            {
              double s = 0;
              for (unsigned int j = 0; j < 4; ++j)
                s += kershaw[i][j] * exact(j);
              b(i) = (hold_node_1 && i == 1 ? 0. : s);
            }
          const unsigned int iterations = solver.solve(b, x, held, 1e-12, 100);
          double             error      = 0;
          for (unsigned int i = 0; i < 4; ++i)
            error = std::max(error, std::abs(x(i) - exact(i)));
          std::cout << name(kind) << ", "
                    << (hold_node_1 ? "node 1 held" : "no node held")
                    << ": |x - x*| below 1e-9: "
                    << (error < 1e-9 ? "yes" : "no")
                    << ", x_1 exactly 0 when held: "
                    << (!hold_node_1 || x(1) == 0. ? "yes" : "no")
                    << ", CG iterations at most 6: "
                    << (iterations <= 6 ? "yes" : "no") << std::endl;
        }

      // b = 0 from a nonzero start vector: x = 0 at once.
      LA::MPI::Vector b(all, comm), x(all, comm);
      for (unsigned int i = 0; i < 4; ++i)
        x(i) = 1. + i;
      const unsigned int iterations = solver.solve(b, x, {}, 1e-12, 100);
      std::cout << name(kind) << ", "
                << "b = 0: x = 0: " << (x.linfty_norm() == 0. ? "yes" : "no")
                << ", CG iterations " << iterations << std::endl;
    }
}
