// Checks RowPatternMatrix, the product from the patterns of repeated rows:
// on the matrix of a grid of equal cells (two unknowns per node, numbered
// along the grid's rows, the rows split over the ranks) the rows fall into
// few patterns, and the product is Epetra's own bit for bit, through Epetra
// and through deal.II's vectors, also after the values change in place; a
// matrix whose rows all differ keeps Epetra's product; and CG with ML built
// on the patterns takes the iterations it takes with ML built on the
// matrix; the ranks agree on whether the patterns are used where only one
// rank's rows repeat. The PETSc operator of the patterns
// (create_pattern_product()) gives the products of the matrix's PETSc copy to
// round-off, and PETSc's CG with GAMG taking its products from it the
// iterations it takes with the copy. The grid has more rows than one task of
// the product takes, so that several threads share it.
#include <vpcontact/linear_algebra/petsc_tools.h>
#include <vpcontact/linear_algebra/row_pattern_matrix.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_Vector.h>
#include <array>
#include <iostream>
#include <petscksp.h>

#include "petsc_cg_iterations.h"

using namespace dealii;
using namespace VPContact;

namespace
{
  constexpr unsigned int n       = 100;   // cells per side
  constexpr unsigned int n_nodes = n + 1; // nodes per side
  constexpr unsigned int n_rows  = 2 * n_nodes * n_nodes;

  /// The unknowns of cell (i, j): two per node, node by node.
  std::array<unsigned int, 8>
  cell_dofs(const unsigned int i, const unsigned int j)
  {
    std::array<unsigned int, 8> dofs;
    const unsigned int          nodes[4] = {j * n_nodes + i,
                                            j * n_nodes + i + 1,
                                            (j + 1) * n_nodes + i,
                                            (j + 1) * n_nodes + i + 1};
    for (unsigned int v = 0; v < 4; ++v)
      for (unsigned int c = 0; c < 2; ++c)
        dofs[2 * v + c] = 2 * nodes[v] + c;
    return dofs;
  }

  /// A symmetric positive definite cell matrix: the Q1 Laplacian's coupled
  /// through the components by [[2, 1], [1, 2]], plus a small mass term.
  double
  cell_entry(const unsigned int a, const unsigned int b)
  {
    const double laplace[4][4]
      = {{4, -1, -1, -2}, {-1, 4, -2, -1}, {-1, -2, 4, -1}, {-2, -1, -1, 4}};
    const double mass[4][4]
      = {{4, 2, 2, 1}, {2, 4, 1, 2}, {2, 1, 4, 2}, {1, 2, 2, 4}};
    const unsigned int va = a / 2, vb = b / 2;
    const double       coupling = (a % 2 == b % 2 ? 2. : 1.);
    return coupling * laplace[va][vb] / 6.
           + (a % 2 == b % 2) * mass[va][vb] / 36.;
  }

  /// The grid's matrix on the owned rows; with @p unique_rows every row is
  /// scaled by its own factor, so that no two rows repeat.
  void
  assemble(TrilinosWrappers::SparseMatrix &matrix,
           const IndexSet                 &owned,
           const bool                      unique_rows)
  {
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          const auto dofs = cell_dofs(i, j);
          for (unsigned int a = 0; a < 8; ++a)
            if (owned.is_element(dofs[a]))
              for (unsigned int b = 0; b < 8; ++b)
                matrix.add(dofs[a],
                           dofs[b],
                           cell_entry(a, b)
                             * (unique_rows ? 1. + 1e-3 * dofs[a] : 1.));
        }
    matrix.compress(VectorOperation::add);
  }

  /// Whether the products of @p patterns and of the matrix agree in every
  /// bit, through Epetra and through deal.II's vectors.
  bool
  same_products(const RowPatternMatrix               &patterns,
                const TrilinosWrappers::SparseMatrix &matrix,
                const IndexSet                       &owned)
  {
    TrilinosWrappers::MPI::Vector x(owned, MPI_COMM_WORLD), y(x), z(x);
    for (const auto i : owned)
      x[i] = std::sin(0.37 * i) + 1e-3 * i;
    x.compress(VectorOperation::insert);
    matrix.vmult(y, x);
    patterns.vmult(z, x);
    bool same = true;
    for (const auto i : owned)
      same = same && y[i] == z[i];
    Epetra_Vector ey(matrix.trilinos_matrix().RangeMap()), ez(ey);
    matrix.trilinos_matrix().Multiply(false, x.trilinos_vector(), ey);
    patterns.Multiply(false, x.trilinos_vector(), ez);
    for (int i = 0; i < ey.MyLength(); ++i)
      same = same && ey[i] == ez[i];
    return Utilities::MPI::min(same ? 1 : 0, MPI_COMM_WORLD) == 1;
  }

  unsigned int
  cg_iterations(const TrilinosWrappers::SparseMatrix &matrix,
                const Epetra_RowMatrix               &ml_matrix,
                const IndexSet                       &owned)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> modes;
    data.set_parameters(parameters, modes, matrix.trilinos_matrix());
    parameters.set("PDE equations", 2);
    TrilinosWrappers::PreconditionAMG amg;
    amg.initialize(ml_matrix, parameters);
    TrilinosWrappers::MPI::Vector x(owned, MPI_COMM_WORLD), b(x);
    for (const auto i : owned)
      b[i] = 1.;
    b.compress(VectorOperation::insert);
    SolverControl                           control(1000, 1e-10 * b.l2_norm());
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    cg.solve(matrix, x, b, amg);
    return control.last_step();
  }



  /// The patterns' PETSc operator against the matrix's PETSc copy: the
  /// largest difference of the products relative to the largest entry,
  /// and, for a symmetric matrix (@p with_cg), the CG iterations with each.
  void
  check_petsc_product(const RowPatternMatrix               &patterns,
                      const TrilinosWrappers::SparseMatrix &matrix,
                      const unsigned int                    rank,
                      const bool                            with_cg)
  {
    Mat A       = copy_to_petsc(matrix, 2);
    Mat product = create_pattern_product(patterns, MPI_COMM_WORLD);
    Vec x, y, z;
    VPContactPetsc(MatCreateVecs(A, &x, &y));
    VPContactPetsc(VecDuplicate(y, &z));
    PetscInt first, last;
    VPContactPetsc(VecGetOwnershipRange(x, &first, &last));
    for (PetscInt i = first; i < last; ++i)
      VPContactPetsc(
        VecSetValue(x, i, std::sin(0.37 * i) + 1e-3 * i, INSERT_VALUES));
    VPContactPetsc(VecAssemblyBegin(x));
    VPContactPetsc(VecAssemblyEnd(x));
    VPContactPetsc(MatMult(A, x, y));
    VPContactPetsc(MatMult(product, x, z));
    PetscReal largest, difference;
    VPContactPetsc(VecNorm(y, NORM_INFINITY, &largest));
    VPContactPetsc(VecAXPY(z, -1., y));
    VPContactPetsc(VecNorm(z, NORM_INFINITY, &difference));
    if (rank == 0)
      std::cout << "PETSc operator of the patterns: products as the PETSc "
                << "copy's to 1e-14: "
                << (difference <= 1e-14 * largest ? "yes" : "NO");
    if (with_cg)
      {
        const PetscInt with_matrix   = petsc_cg_iterations(A, A, y);
        const PetscInt with_patterns = petsc_cg_iterations(product, A, y);
        if (rank == 0)
          std::cout << "; CG with GAMG converges: "
                    << (with_patterns > 0 ? "yes" : "NO")
                    << ", within one iteration of the copy's: "
                    << (std::abs(with_patterns - with_matrix) <= 1 ? "yes" :
                                                                     "NO");
      }
    if (rank == 0)
      std::cout << std::endl;
    VecDestroy(&x);
    VecDestroy(&y);
    VecDestroy(&z);
    MatDestroy(&product);
    MatDestroy(&A);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc,
                                       argv,
                                       numbers::invalid_unsigned_int);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const unsigned int rank    = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  // Contiguous blocks of whole nodes per rank.
  const unsigned int per_rank = 2 * (n_nodes * n_nodes / n_ranks);
  IndexSet           owned(n_rows);
  owned.add_range(rank * per_rank,
                  rank + 1 == n_ranks ? n_rows : (rank + 1) * per_rank);

  DynamicSparsityPattern pattern(n_rows, n_rows, owned);
  for (unsigned int j = 0; j < n; ++j)
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto dofs = cell_dofs(i, j);
        for (const auto a : dofs)
          if (owned.is_element(a))
            for (const auto b : dofs)
              pattern.add(a, b);
      }

  TrilinosWrappers::SparseMatrix matrix;
  matrix.reinit(owned, owned, pattern, MPI_COMM_WORLD);
  assemble(matrix, owned, false);
  RowPatternMatrix patterns(matrix.trilinos_matrix());
  // Interior rows: 2 patterns; the rows at the grid's edges and corners
  // (16 more for each component), and those beside another rank's
  // columns, add theirs.
  const std::uint64_t n_patterns = patterns.n_patterns();
  if (rank == 0)
    std::cout << "grid matrix: compressed "
              << (patterns.compressed() ? "yes" : "NO")
              << ", at most 5 % of the rows are patterns: "
              << (n_patterns <= n_rows / 20 ? "yes" : "NO") << std::endl;
  const bool same = same_products(patterns, matrix, owned);
  if (rank == 0)
    std::cout << "products identical: " << (same ? "yes" : "NO") << std::endl;

  check_petsc_product(patterns, matrix, rank, true);

  // The values change in place (the pattern stays): update() takes them.
  matrix *= 1.5;
  patterns.update();
  const bool same_scaled = same_products(patterns, matrix, owned);
  if (rank == 0)
    std::cout << "after a change of the values and update(): identical "
              << (same_scaled ? "yes" : "NO") << std::endl;

  const unsigned int with_matrix
    = cg_iterations(matrix, matrix.trilinos_matrix(), owned);
  const unsigned int with_patterns = cg_iterations(matrix, patterns, owned);
  if (rank == 0)
    std::cout << "CG with ML built on the patterns: " << with_patterns
              << " iterations, as with ML built on the matrix: "
              << (with_patterns == with_matrix ? "yes" : "NO") << std::endl;

  matrix = 0;
  assemble(matrix, owned, true);
  patterns.update();
  const bool same_unique = same_products(patterns, matrix, owned);
  if (rank == 0)
    std::cout << "rows that all differ: compressed "
              << (patterns.compressed() ? "YES" : "no")
              << ", products identical: " << (same_unique ? "yes" : "NO")
              << std::endl;

  // Only the last rank's rows all differ (on one rank: all rows). The
  // ranks agree on compressed() all the same, and the last rank's products
  // are the matrix's: with 2 ranks the solvers take the patterns (and
  // the PETSc operator is created on every rank), with 1 they do not.
  matrix = 0;
  assemble(matrix, owned, rank + 1 == n_ranks);
  patterns.update();
  const int  compressed = patterns.compressed() ? 1 : 0;
  const bool agree      = Utilities::MPI::min(compressed, MPI_COMM_WORLD)
                     == Utilities::MPI::max(compressed, MPI_COMM_WORLD);
  const bool same_mixed = same_products(patterns, matrix, owned);
  if (rank == 0)
    std::cout << "the last rank's rows all differ: compressed "
              << (compressed ? "yes" : "no")
              << ", the same on every rank: " << (agree ? "yes" : "NO")
              << ", products identical: " << (same_mixed ? "yes" : "NO")
              << std::endl;
  check_petsc_product(patterns, matrix, rank, false);
}
