// Unit test: LinearSolver keeps its Cholesky factors through a change of a
// few rows and columns of the matrix (as when nodes enter or leave the stick
// set and their unknowns' constraints change), and CG preconditioned by them
// solves the changed matrix within the bound that keeps_through() assumes:
// at most 2r + 1 iterations for r changed rows. keeps_through() allows r
// rows while 1 + 2r stays within the 10 iterations at which the factors are
// rebuilt, counting the rows of earlier changes. The matrix is the
// five-point Laplacian of a 40 x 40 grid plus the identity; a change
// constrains some rows as AffineConstraints do in assembly (their row and
// column zero, the diagonal kept). The right-hand side is K e with the
// constrained rows' entries zero.
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <vector>

#include "grid_matrix.h"

using namespace VPContact;

namespace
{
  // Zero the rows and columns of @p rows but their diagonal entries.
  void
  constrain(LA::SparseMatrix &K, const std::vector<unsigned int> &rows)
  {
    for (const unsigned int r : rows)
      for (auto entry = K.begin(r); entry != K.end(r); ++entry)
        if (entry->column() != r)
          {
            K.set(r, entry->column(), 0.);
            K.set(entry->column(), r, 0.);
          }
    K.compress(VectorOperation::insert);
  }



  // Solves K x = b, b = K e with the constrained entries zero; prints the
  // iterations against the bound 2r + 1 and the residual.
  void
  check_solve(LinearSolver                    &solver,
              const LA::SparseMatrix          &K,
              const IndexSet                  &all,
              const std::vector<unsigned int> &constrained,
              const unsigned int               changed_rows)
  {
    LA::MPI::Vector e(all, MPI_COMM_WORLD), b(e), x(e);
    e = 1.;
    for (const unsigned int r : constrained)
      e[r] = 0.;
    K.vmult(b, e);
    const unsigned int iterations = solver.solve(x, b);
    LA::MPI::Vector    r(e);
    K.vmult(r, x);
    r -= b;
    std::printf("  CG iterations <= 2 * %u + 1: %s; |K x - b| <= 1e-10 |b|: "
                "%s\n",
                changed_rows,
                iterations <= 2 * changed_rows + 1 ? "yes" : "no",
                r.l2_norm() <= 1e-10 * b.l2_norm() ? "yes" : "no");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               m   = 40;
  const IndexSet                   all = grid_rows(m);
  LA::SparseMatrix                 K;
  grid_matrix(m, 1., K);
  const NearNullSpace constants;

  LinearSolver solver = grid_linear_solver("Cholesky");
  solver.initialize(K, constants);
  std::vector<unsigned int> constrained;
  for (const std::vector<unsigned int> &change :
       {std::vector<unsigned int>{41, 42, 43}, {300}, {900}})
    {
      std::printf("%zu more rows constrained (%zu in all): kept: %s\n",
                  change.size(),
                  constrained.size() + change.size(),
                  solver.keeps_through(change.size()) ? "yes" : "no");
      constrained.insert(constrained.end(), change.begin(), change.end());
      constrain(K, change);
      if (solver.keeps_through(change.size()))
        solver.rows_changed(change.size());
      else
        solver.initialize(K, constants);
      check_solve(solver, K, all, constrained, constrained.size());
    }
  const auto [builds, updates] = solver.n_builds_and_updates();
  std::printf("factorizations: %u new, %u with the order kept\n",
              builds,
              updates);
}
