// What the unit tests of DamageRegionSolver share: the names of its
// preconditioners, the solver's rows of a matrix, the model problem with the
// left quarter held, and (from damage_matrix_tools.h) the damage matrix of a
// model problem and its copy into a Trilinos matrix with given owned rows.
#ifndef vpcontact_tests_damage_region_test_tools_h
#define vpcontact_tests_damage_region_test_tools_h

#include <vpcontact/damage/damage_region_solver.h>
#include <vpcontact/linear_algebra/owned_rows.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "damage_matrix_tools.h"

namespace VPContact
{
  namespace DamageRegionTestTools
  {
    using DamageMatrixTools::DenseMatrix;

    /// The name a test prints for a preconditioner.
    inline const char *
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

    // The model problem's matrix and its copy into Trilinos, shared with
    // the tests of the damage bounds.
    using DamageMatrixTools::contiguous_rows;
    using DamageMatrixTools::copy_to_trilinos;
    using DamageMatrixTools::q1_damage_matrix;



    /// The Trilinos copy of a dense matrix's rows @p owned and the solver's
    /// view of them (OwnedRows reads the matrix, so both stay together and
    /// in place).
    struct RegionRows
    {
      RegionRows(const DenseMatrix &K, const IndexSet &owned, MPI_Comm comm)
      {
        copy_to_trilinos(K, owned, comm, matrix);
        rows.reinit(matrix, owned, comm);
      }

      RegionRows(const RegionRows &) = delete;
      RegionRows &
      operator=(const RegionRows &)
        = delete;

      LA::SparseMatrix matrix;
      OwnedRows        rows;
    };



    /// K = M_L/k + kappa A on an n x n grid (q1_damage_matrix()) with the
    /// nodes of the left quarter (x < 1/4) held at 0, the rows split into
    /// contiguous parts of the ranks (a horizontal cut through the free
    /// nodes), and a smooth x* that vanishes on the held nodes: b = K x* is
    /// the right-hand side whose solution the tests know.
    struct HeldQuarterProblem
    {
      HeldQuarterProblem(const unsigned int n,
                         const double       kappa,
                         const double       k,
                         MPI_Comm           comm)
        : comm(comm)
        , nodes((n + 1) * (n + 1))
        , K(q1_damage_matrix(n, kappa, k))
        , exact(nodes, 0.)
        , held(nodes, false)
        , owned(contiguous_rows(nodes, comm))
        , region(K, owned, comm)
      {
        const double h = 1. / n;
        for (unsigned int y = 0; y <= n; ++y)
          for (unsigned int x = 0; x <= n; ++x)
            {
              const unsigned int i = y * (n + 1) + x;
              held[i]              = (4 * x < n);
              if (!held[i])
                exact[i] = 1. + std::sin(3. * x * h) * std::cos(2. * y * h);
            }
      }

      /// b = K x* on the free rows, 0 on the held ones, and the positions
      /// of this rank's held rows within its owned ones (the solver's
      /// numbering).
      void
      right_hand_side(LA::MPI::Vector           &b,
                      std::vector<unsigned int> &held_positions) const
      {
        b.reinit(owned, comm);
        held_positions.clear();
        for (const auto i : owned)
          {
            double s = 0;
            for (unsigned int j = 0; j < nodes; ++j)
              s += K[i][j] * exact[j];
            b(i) = (held[i] ? 0. : s);
            if (held[i])
              held_positions.push_back(owned.index_within_set(i));
          }
      }

      /// max |x - x*| over all ranks.
      double
      error(const LA::MPI::Vector &x) const
      {
        double error = 0;
        for (const auto i : owned)
          error = std::max(error, std::abs(x(i) - exact[i]));
        return Utilities::MPI::max(error, comm);
      }

      const MPI_Comm      comm;
      const unsigned int  nodes;
      const DenseMatrix   K;
      std::vector<double> exact;
      std::vector<bool>   held;
      const IndexSet      owned;
      RegionRows          region;
    };
  } // namespace DamageRegionTestTools
} // namespace VPContact

#endif
