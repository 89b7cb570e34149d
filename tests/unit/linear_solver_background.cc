// Unit test: LinearSolver::initialize_in_background() with Linear solver =
// Cholesky. The caller goes on while the factorization runs; the first
// solve waits for it and solves to round-off; a factorization that breaks
// down reports its error at the first use of the factors, and clear() after
// one that nobody waited for (the path of a destructor) does not throw.
// The matrix is the five-point Laplacian of a 300 x 300 grid plus a shift,
// so K x = K e has the solution e = (1, ..., 1).
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <string>

#include "grid_matrix.h"

using namespace VPContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               m   = 300;
  const IndexSet                   all = grid_rows(m);

  {
    LA::SparseMatrix K;
    grid_matrix(m, 1., K);
    LinearSolver solver = grid_linear_solver("Cholesky");
    solver.initialize_in_background(K, NearNullSpace());
    // Work beside the factorization: the right-hand side K e.
    LA::MPI::Vector e(all, MPI_COMM_WORLD), b(e), x(e);
    e = 1.;
    K.vmult(b, e);
    const unsigned int iterations = solver.solve(x, b);
    x -= e;
    std::printf("solve after a background factorization: %u iteration(s), "
                "|x - e|_inf < 1e-12: %s\n",
                iterations,
                x.linfty_norm() < 1e-12 ? "yes" : "no");
  }

  // A shift of -1 makes the matrix indefinite (see unit/sparse_cholesky).
  LA::SparseMatrix K;
  grid_matrix(m, -1., K);
  {
    LinearSolver solver = grid_linear_solver("Cholesky");
    solver.initialize_in_background(K, NearNullSpace());
    LA::MPI::Vector b(all, MPI_COMM_WORLD), x(b);
    b = 1.;
    try
      {
        solver.solve(x, b);
        std::printf("indefinite matrix solved: wrong\n");
      }
    catch (const std::exception &error)
      {
        const std::string message = error.what();
        std::printf("indefinite matrix refused at the first solve: %s\n",
                    message.find("not positive definite") != std::string::npos ?
                      "yes" :
                      "no");
      }
  }
  {
    LinearSolver solver = grid_linear_solver("Cholesky");
    solver.initialize_in_background(K, NearNullSpace());
    solver.clear();
    std::printf("clear() after a failed background factorization: no "
                "exception\n");
  }
}
