// Unit test: the modified incomplete Cholesky factorization MIC(0) of
// DamageRegionSolver keeps the row sums of the matrix, L L^T 1 = K 1. On
// K = M_L/k + kappa A for Q1 elements on an 8 x 8 grid of squares (an
// M-matrix with non-negative row sums), the right-hand side b = K 1 is then
// solved by the first CG iteration: the preconditioned residual of the zero
// start vector is 1 itself, and its step length is 1. IC(0), which drops
// its fill-in instead, needs more. Both converge to x = 1.
#include <vpcontact/damage_region_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cmath>
#include <iostream>

using namespace VPContact;

namespace
{
  const char *
  name(const DamageRegionSolver::Preconditioner kind)
  {
    switch (kind)
      {
        case DamageRegionSolver::Preconditioner::incomplete_cholesky:
          return "IC(0)";
        case DamageRegionSolver::Preconditioner::modified_incomplete_cholesky:
          return "MIC(0)";
        default:
          return "modified diagonal IC (Eisenstat)";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_SELF;

  // Q1 on a square, node (a, b) of the cell at (x + a, y + b): the stiffness
  // is 2/3 on the diagonal, -1/6 between the ends of an edge and -1/3 across
  // the diagonal; the lumped mass h^2/4 per node.
  const unsigned int n = 8, nodes = (n + 1) * (n + 1);
  const double       h = 1. / n, kappa = 0.01, k = 0.01;
  const auto         node
    = [&](unsigned int x, unsigned int y) { return y * (n + 1) + x; };
  std::vector<std::vector<double>> K(nodes, std::vector<double>(nodes, 0.));
  for (unsigned int x = 0; x < n; ++x)
    for (unsigned int y = 0; y < n; ++y)
      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int b = 0; b < 4; ++b)
          {
            const unsigned int ia = node(x + a % 2, y + a / 2);
            const unsigned int ib = node(x + b % 2, y + b / 2);
            const unsigned int d  = (a % 2 != b % 2) + (a / 2 != b / 2);
            K[ia][ib] += kappa
                           * (d == 0 ? 2. / 3. :
                              d == 1 ? -1. / 6. :
                                       -1. / 3.)
                         + (d == 0 ? h * h / 4. / k : 0.);
          }

  IndexSet               all = complete_index_set(nodes);
  DynamicSparsityPattern pattern(nodes, nodes);
  for (unsigned int i = 0; i < nodes; ++i)
    for (unsigned int j = 0; j < nodes; ++j)
      if (K[i][j] != 0.)
        pattern.add(i, j);
  TrilinosWrappers::SparseMatrix matrix;
  matrix.reinit(all, all, pattern, comm);
  for (unsigned int i = 0; i < nodes; ++i)
    for (unsigned int j = 0; j < nodes; ++j)
      if (K[i][j] != 0.)
        matrix.set(i, j, K[i][j]);
  matrix.compress(VectorOperation::insert);

  for (const auto kind :
       {DamageRegionSolver::Preconditioner::modified_incomplete_cholesky,
        DamageRegionSolver::Preconditioner::incomplete_cholesky,
        DamageRegionSolver::Preconditioner::diagonal})
    {
      DamageRegionSolver solver;
      solver.initialize(matrix, all, comm, kind);
      solver.begin_step();
      TrilinosWrappers::MPI::Vector b(all, comm), x(all, comm);
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
