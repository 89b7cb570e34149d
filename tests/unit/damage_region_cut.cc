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

  const unsigned int n = 32, nodes = (n + 1) * (n + 1);
  const double       h = 1. / n, kappa = 0.01, k = 1.;
  const auto         node
    = [&](unsigned int x, unsigned int y) { return y * (n + 1) + x; };
  const DenseMatrix K = q1_damage_matrix(n, kappa, k);

  std::vector<double> exact(nodes, 0.);
  std::vector<bool>   held(nodes, false);
  for (unsigned int y = 0; y <= n; ++y)
    for (unsigned int x = 0; x <= n; ++x)
      {
        held[node(x, y)] = (4 * x < n);
        if (!held[node(x, y)])
          exact[node(x, y)] = 1. + std::sin(3. * x * h) * std::cos(2. * y * h);
      }

  const IndexSet   owned = contiguous_rows(nodes, comm);
  LA::SparseMatrix matrix;
  copy_to_trilinos(K, owned, comm, matrix);
  OwnedRows rows;
  rows.reinit(matrix, owned, comm);

  for (const auto kind :
       {DamageRegionSolver::Preconditioner::modified_incomplete_cholesky,
        DamageRegionSolver::Preconditioner::diagonal})
    {
      DamageRegionSolver solver;
      solver.initialize(rows, kind);
      solver.begin_step();
      LA::MPI::Vector           b(owned, comm), x(owned, comm);
      std::vector<unsigned int> held_positions;
      for (const auto i : owned)
        {
          double s = 0;
          for (unsigned int j = 0; j < nodes; ++j)
            s += K[i][j] * exact[j];
          b(i) = (held[i] ? 0. : s);
          if (held[i])
            held_positions.push_back(owned.index_within_set(i));
        }
      const unsigned int iterations
        = solver.solve(b, x, held_positions, 1e-12, 500);
      double error = 0;
      for (const auto i : owned)
        error = std::max(error, std::abs(x(i) - exact[i]));
      error = Utilities::MPI::max(error, comm);
      if (rank == 0)
        std::cout << name(kind)
                  << ": |x - x*| below 1e-9: " << (error < 1e-9 ? "yes" : "no")
                  << ", CG iterations: " << iterations << std::endl;
    }
}
