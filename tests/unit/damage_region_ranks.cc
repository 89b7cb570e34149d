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

  // The Q1 damage matrix of a 16 x 16 grid (see q1_damage_matrix()).
  const unsigned int n = 16, nodes = (n + 1) * (n + 1);
  const double       h = 1. / n, kappa = 0.01, k = 0.01;
  const auto         node
    = [&](unsigned int x, unsigned int y) { return y * (n + 1) + x; };
  const DenseMatrix K = q1_damage_matrix(n, kappa, k);

  // x*: smooth, zero on the held nodes (x < 1/4).
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
       {DamageRegionSolver::Preconditioner::incomplete_cholesky,
        DamageRegionSolver::Preconditioner::modified_incomplete_cholesky,
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
      solver.solve(b, x, held_positions, 1e-12, 200);
      double error = 0;
      bool   zero  = true;
      for (const auto i : owned)
        {
          error = std::max(error, std::abs(x(i) - exact[i]));
          zero  = zero && (!held[i] || x(i) == 0.);
        }
      error = Utilities::MPI::max(error, comm);
      zero  = (Utilities::MPI::min(zero ? 1 : 0, comm) == 1);
      if (rank == 0)
        std::cout << name(kind)
                  << ": |x - x*| below 1e-9: " << (error < 1e-9 ? "yes" : "no")
                  << ", held nodes exactly 0: " << (zero ? "yes" : "no")
                  << std::endl;
    }
}
