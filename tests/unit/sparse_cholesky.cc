// Unit test: the sparse Cholesky factorization (SparseCholesky, CHOLMOD).
// For the 1d Laplacian tridiag(-1, 2, -1) of size n the solution of K x = e_1
// is known, x_i = (n + 1 - i) / (n + 1), and K x = K y recovers any y to
// round-off; a second solve with the same factors must do the same. The
// same on the 2d Laplacian of an 80 x 80 grid, whose factor has supernodes
// of up to a separator's width (about 80 columns) with rows below them: the
// substitutions over the supernodes are the program's own (see
// SparseCholesky::forward_substitution()), and this is where their blocks
// of four columns, the columns left over, and the rows below the diagonal
// blocks are all used; and in two threads, over the two groups of subtrees
// of the elimination tree (SupernodePartition), to the same bits. A matrix
// that is not positive definite is refused with a message that names the
// column where the factorization broke down. The factorization may use two
// BLAS threads (set_blas_threads()): it gives the same solution, and leaves
// the BLAS at one thread, the program's setting. The thread count is read
// back from every OpenBLAS library loaded: the test fails if the count is
// not reached (the libraries not found, or only one of them set). It does
// not see whether threads start: the serial OpenBLAS keeps the count too.
#include <vpcontact/sparse_cholesky.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cmath>
#include <dlfcn.h>
#include <iostream>

using namespace VPContact;

namespace
{
  // The n x n tridiagonal matrix with @p diagonal and -1 beside it.
  void
  make_tridiagonal(TrilinosWrappers::SparseMatrix &matrix,
                   const unsigned int              n,
                   const std::vector<double>      &diagonal)
  {
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j < std::min(n, i + 2); ++j)
        dsp.add(i, j);
    matrix.reinit(complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      {
        matrix.set(i, i, diagonal[i]);
        if (i > 0)
          matrix.set(i, i - 1, -1.);
        if (i + 1 < n)
          matrix.set(i, i + 1, -1.);
      }
    matrix.compress(VectorOperation::insert);
  }

  // The 5-point Laplacian of an m x m grid of unknowns, Dirichlet around.
  void
  make_laplacian_2d(TrilinosWrappers::SparseMatrix &matrix,
                    const unsigned int              m)
  {
    const unsigned int     n = m * m;
    DynamicSparsityPattern dsp(n, n);
    const auto             neighbours = [m](const unsigned int i) {
      std::vector<unsigned int> result = {i};
      const unsigned int        row = i / m, column = i % m;
      if (column > 0)
        result.push_back(i - 1);
      if (column + 1 < m)
        result.push_back(i + 1);
      if (row > 0)
        result.push_back(i - m);
      if (row + 1 < m)
        result.push_back(i + m);
      return result;
    };
    for (unsigned int i = 0; i < n; ++i)
      for (const unsigned int j : neighbours(i))
        dsp.add(i, j);
    matrix.reinit(complete_index_set(n), dsp, MPI_COMM_WORLD);
    for (unsigned int i = 0; i < n; ++i)
      for (const unsigned int j : neighbours(i))
        matrix.set(i, j, i == j ? 4. : -1.);
    matrix.compress(VectorOperation::insert);
  }

  // The thread counts of the OpenBLAS libraries that are loaded (Debian's
  // OpenBLAS loads as libblas.so.3 and libopenblas.so.0).
  std::string
  blas_threads()
  {
    std::string text;
    using Getter = int (*)();
    for (const char *library : {"libblas.so.3", "libopenblas.so.0"})
      if (void *handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD))
        {
          if (const auto getter = reinterpret_cast<Getter>(
                dlsym(handle, "openblas_get_num_threads")))
            text += std::string(text.empty() ? "" : ", ") + library + ": "
                    + std::to_string(getter());
          dlclose(handle);
        }
    return text.empty() ? "no OpenBLAS loaded" : text;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int               n = 50;
  TrilinosWrappers::SparseMatrix   laplacian;
  make_tridiagonal(laplacian, n, std::vector<double>(n, 2.));

  set_blas_threads(2);
  std::cout << "BLAS threads after set_blas_threads(2): " << blas_threads()
            << std::endl;
  SparseCholesky cholesky;
  cholesky.factorize(laplacian, 2);
  std::cout << "BLAS threads after a factorization in 2: " << blas_threads()
            << std::endl;
  std::cout << "n = " << n << ", nonzeros of L: " << cholesky.factor_nonzeros()
            << " (a tridiagonal matrix fills nothing: 2n - 1 = " << 2 * n - 1
            << ")" << std::endl;

  // K x = e_1.
  TrilinosWrappers::MPI::Vector b(complete_index_set(n), MPI_COMM_WORLD);
  TrilinosWrappers::MPI::Vector x(b);
  b(0) = 1.;
  cholesky.solve(x, b);
  double error = 0;
  for (unsigned int i = 0; i < n; ++i)
    error = std::max(error, std::abs(x(i) - (n - i) / (n + 1.)));
  std::cout << "K x = e_1: largest error against (n + 1 - i)/(n + 1): "
            << (error < 1e-12 ? "below 1e-12" : std::to_string(error))
            << std::endl;

  // K x = K y, for y_i = sin(i), with the same factors.
  TrilinosWrappers::MPI::Vector y(b);
  for (unsigned int i = 0; i < n; ++i)
    y(i) = std::sin(i);
  laplacian.vmult(b, y);
  cholesky.solve(x, b);
  x -= y;
  std::cout << "K x = K y, second solve: |x - y|_inf "
            << (x.linfty_norm() < 1e-12 ? "below 1e-12" :
                                          std::to_string(x.linfty_norm()))
            << std::endl;

  // The 2d Laplacian: K x = K y, for y_i = sin(i), relative to |y|_inf.
  {
    const unsigned int             m = 80;
    TrilinosWrappers::SparseMatrix laplacian_2d;
    make_laplacian_2d(laplacian_2d, m);
    SparseCholesky cholesky_2d;
    cholesky_2d.factorize(laplacian_2d);
    TrilinosWrappers::MPI::Vector y_2d(complete_index_set(m * m),
                                       MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector b_2d(y_2d), x_2d(y_2d);
    for (unsigned int i = 0; i < m * m; ++i)
      y_2d(i) = std::sin(i);
    laplacian_2d.vmult(b_2d, y_2d);
    cholesky_2d.solve(x_2d, b_2d);
    x_2d -= y_2d;
    const double relative_error = x_2d.linfty_norm() / y_2d.linfty_norm();
    std::cout << "2d Laplacian, " << m << " x " << m
              << " grid: K x = K y, |x - y|_inf / |y|_inf "
              << (relative_error < 1e-10 ? "below 1e-10" :
                                           std::to_string(relative_error))
              << std::endl;

    // The substitutions in two threads, on the two groups of subtrees of
    // the elimination tree: both groups must hold supernodes, and the
    // result must be the same bits as in one thread.
    const SupernodePartition &partition = cholesky_2d.supernode_partition();
    std::cout << "2d Laplacian: supernodes in the two groups and the top: "
              << (!partition.groups[0].empty() && !partition.groups[1].empty() ?
                    "both groups hold some" :
                    "a group is EMPTY")
              << ", top " << (partition.top.empty() ? "EMPTY" : "not empty")
              << std::endl;
    TrilinosWrappers::MPI::Vector x_one(y_2d), x_two(y_2d);
    cholesky_2d.solve(x_one, b_2d, 1);
    cholesky_2d.solve(x_two, b_2d, 2);
    bool same_bits = true;
    for (unsigned int i = 0; i < m * m; ++i)
      same_bits = same_bits && x_one(i) == x_two(i);
    x_two -= y_2d;
    std::cout << "2d Laplacian, two threads: the same bits as one thread: "
              << (same_bits ? "yes" : "NO") << ", |x - y|_inf / |y|_inf "
              << (x_two.linfty_norm() / y_2d.linfty_norm() < 1e-10 ?
                    "below 1e-10" :
                    std::to_string(x_two.linfty_norm() / y_2d.linfty_norm()))
              << std::endl;
  }

  // diag(2, ..., 2, 0.5, 2, ...) with -1 beside it: the pivot of row 10
  // becomes 0.5 - 10/11 < 0.
  std::vector<double> diagonal(n, 2.);
  diagonal[10] = 0.5;
  TrilinosWrappers::SparseMatrix indefinite;
  make_tridiagonal(indefinite, n, diagonal);
  try
    {
      cholesky.factorize(indefinite);
      std::cout << "the indefinite matrix was NOT refused" << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      std::cout << "indefinite matrix refused: ";
      e.print_info(std::cout);
      std::cout << std::endl;
    }
}
