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

using namespace VPContact;

namespace
{
  // The m^2 x m^2 matrix with diagonal 4 + shift and -1 for each grid
  // neighbour.
  void
  grid_matrix(const unsigned int m, const double shift, LA::SparseMatrix &K)
  {
    const unsigned int n = m * m;
    IndexSet           all(n);
    all.add_range(0, n);
    LA::SparsityPattern pattern(all, MPI_COMM_WORLD, 5);
    const auto          neighbours = [m](const unsigned int i) {
      std::vector<unsigned int> list{i};
      const unsigned int        x = i % m, y = i / m;
      if (x > 0)
        list.push_back(i - 1);
      if (x + 1 < m)
        list.push_back(i + 1);
      if (y > 0)
        list.push_back(i - m);
      if (y + 1 < m)
        list.push_back(i + m);
      return list;
    };
    for (unsigned int i = 0; i < n; ++i)
      for (const unsigned int j : neighbours(i))
        pattern.add(i, j);
    pattern.compress();
    K.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      for (const unsigned int j : neighbours(i))
        K.set(i, j, i == j ? 4. + shift : -1.);
    K.compress(VectorOperation::insert);
  }



  void
  check_solve(const unsigned int m)
  {
    LA::SparseMatrix K;
    grid_matrix(m, 1., K);
    IndexSet all(m * m);
    all.add_range(0, m * m);
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
