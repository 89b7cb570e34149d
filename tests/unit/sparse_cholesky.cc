// Unit test: SparseCholesky factorizes small matrices column by column and
// large ones by supernodes, and both solve to round-off; an indefinite
// matrix is refused with the pivot named. The matrix is the five-point
// Laplacian of an m x m grid plus the identity, so the solution of K x = K e
// is e = (1, ..., 1) exactly.
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/sparse_cholesky.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <string>

#include "grid_matrix.h"

using namespace VPContact;

namespace
{
  void
  check_solve(const unsigned int m)
  {
    LA::SparseMatrix K;
    grid_matrix(m, 1., K);
    const IndexSet  all = grid_rows(m);
    LA::MPI::Vector e(all, MPI_COMM_WORLD), b(e), x(e);
    e = 1.;
    K.vmult(b, e);
    SparseCholesky factors;
    factors.factorize(K);
    factors.solve(x, b);
    x -= e;
    std::printf("%u x %u grid (%u unknowns): %s, |x - e|_inf < 1e-12: %s\n",
                m,
                m,
                m * m,
                factors.is_supernodal() ? "supernodal" : "simplicial",
                x.linfty_norm() < 1e-12 ? "yes" : "no");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_solve(20);
  check_solve(300);

  // A shift of -1 makes the matrix indefinite (the Laplacian's smallest
  // eigenvalue is 0.045 here) with a positive diagonal: the first pivots
  // are positive, and a later one is not, where the factorization must
  // stop (an L D L^T factorization would go through).
  LA::SparseMatrix K;
  grid_matrix(20, -1., K);
  SparseCholesky factors;
  try
    {
      factors.factorize(K);
      std::printf("indefinite matrix factorized: wrong\n");
    }
  catch (const std::exception &error)
    {
      const std::string message = error.what();
      std::printf("indefinite matrix refused: %s\n",
                  message.find("not positive definite") != std::string::npos ?
                    "yes" :
                    "no");
    }
}
