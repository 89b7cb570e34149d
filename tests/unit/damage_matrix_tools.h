// What the unit tests of the damage bounds share: the damage matrix of a
// model problem and its copy into a Trilinos matrix with given owned rows.
#ifndef vpcontact_tests_damage_matrix_tools_h
#define vpcontact_tests_damage_matrix_tools_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace VPContact
{
  namespace DamageMatrixTools
  {
    using DenseMatrix = std::vector<std::vector<double>>;

    /// K = M_L/k + kappa A for Q1 elements on an n x n grid of squares of
    /// the unit square, node (x, y) numbered y (n + 1) + x. On a square
    /// cell the stiffness is 2/3 on the diagonal, -1/6 between the ends of
    /// an edge and -1/3 across the cell; the lumped mass is h^2/4 per node
    /// and cell. An M-matrix with non-negative row sums, like the damage
    /// matrix of the paper's meshes.
    inline DenseMatrix
    q1_damage_matrix(const unsigned int n, const double kappa, const double k)
    {
      const unsigned int nodes = (n + 1) * (n + 1);
      const double       h     = 1. / n;
      const auto         node
        = [&](unsigned int x, unsigned int y) { return y * (n + 1) + x; };
      DenseMatrix K(nodes, std::vector<double>(nodes, 0.));
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
      return K;
    }

    /// The rows of a matrix with @p size rows that this rank owns:
    /// contiguous blocks of about equal size, in the order of the ranks.
    inline IndexSet
    contiguous_rows(const unsigned int size, const MPI_Comm comm)
    {
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
      IndexSet           owned(size);
      owned.add_range(rank * size / n_ranks, (rank + 1) * size / n_ranks);
      return owned;
    }

    /// The rows of K that this rank owns, with their nonzero entries, in a
    /// Trilinos matrix (square: the columns distributed as the rows).
    inline void
    copy_to_trilinos(const DenseMatrix &K,
                     const IndexSet    &owned,
                     const MPI_Comm     comm,
                     LA::SparseMatrix  &matrix)
    {
      const unsigned int     size = K.size();
      DynamicSparsityPattern pattern(size, size);
      for (const auto i : owned)
        for (unsigned int j = 0; j < size; ++j)
          if (K[i][j] != 0.)
            pattern.add(i, j);
      matrix.reinit(owned, owned, pattern, comm);
      for (const auto i : owned)
        for (unsigned int j = 0; j < size; ++j)
          if (K[i][j] != 0.)
            matrix.set(i, j, K[i][j]);
      matrix.compress(VectorOperation::insert);
    }
  } // namespace DamageMatrixTools
} // namespace VPContact

#endif
