// Unit test: LinearSolver with CG and AMG after its matrix changed in place
// by so much that the preconditioner built for the old matrix does not
// converge within its limit (LinearSolver::matrix_changed()). The solve then
// builds AMG anew, and must hand it the caller's near null space again, not
// a copy that is gone after the rebuild: the test changes the matrix twice,
// so that the second rebuild reads what the first one kept. The matrix is
// the five-point Laplacian of a 60 x 60 grid plus a shift, its diagonal then
// raised by 10^6 on every second (then every third) row; the right-hand
// side is K e, e = (1, ..., 1).
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

#include <deal.II/base/mpi.h>

#include <cstdio>

#include "grid_matrix.h"

using namespace VPContact;

namespace
{



  // Solves K x = K e and prints whether the residual is within the solver's
  // relative tolerance (10^-10 by default) and whether the solver still
  // refers to the caller's near null space.
  void
  check_solve(const char             *what,
              LinearSolver           &solver,
              const LA::SparseMatrix &K,
              const IndexSet         &all,
              const NearNullSpace    &modes)
  {
    LA::MPI::Vector e(all, MPI_COMM_WORLD), b(e), x(e);
    e = 1.;
    K.vmult(b, e);
    solver.solve(x, b);
    LA::MPI::Vector r(e);
    K.vmult(r, x);
    r -= b;
    std::printf("%s: |K x - b| <= 1e-10 |b|: %s; AMG keeps the caller's "
                "near null space: %s\n",
                what,
                r.l2_norm() <= 1e-10 * b.l2_norm() ? "yes" : "no",
                solver.rebuild_near_null_space() == &modes ? "yes" : "no");
  }



  // Adds 10^6 to the diagonal entry of every @p stride-th row.
  void
  raise_diagonal(LA::SparseMatrix &K, const unsigned int stride)
  {
    for (unsigned int i = 0; i < K.m(); i += stride)
      K.add(i, i, 1e6);
    K.compress(VectorOperation::add);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               m   = 60;
  const IndexSet                   all = grid_rows(m);

  LA::SparseMatrix K;
  grid_matrix(m, 1., K);
  const NearNullSpace modes = constant_modes(all);

  LinearSolver solver = grid_linear_solver("CG with AMG");
  solver.initialize(K, modes);
  check_solve("built for the matrix", solver, K, all, modes);

  raise_diagonal(K, 2);
  solver.matrix_changed();
  check_solve("first change, rebuilt", solver, K, all, modes);

  raise_diagonal(K, 3);
  solver.matrix_changed();
  check_solve("second change, rebuilt again", solver, K, all, modes);
}
