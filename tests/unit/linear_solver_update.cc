// Unit test: LinearSolver::initialize() called again for a matrix whose
// values changed in place, as after a change of the stick set. With
// Cholesky (CHOLMOD) and with PETSc's MUMPS it factorizes with the order
// and symbolic factorization of the first factorization and gives the bits
// of a new factorization; a change that leaves the matrix indefinite is
// refused by CHOLMOD as by a new factorization, and the next change is
// factorized again. AMG is built anew each time. A
// matrix with a new pattern is always built anew. The matrix is the
// five-point Laplacian of an m x m grid plus the identity; the change
// raises the diagonal of every fifth row by 3 and halves the coupling of
// every seventh row to its right neighbour (and that neighbour's to it),
// which keeps the matrix symmetric positive definite. The right-hand side is
// K e, e = (1, ..., 1).
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <string>

#include "grid_matrix.h"

using namespace VPContact;

namespace
{
  void
  change_values(LA::SparseMatrix &K, const unsigned int m)
  {
    for (unsigned int i = 0; i < K.m(); i += 5)
      K.add(i, i, 3.);
    for (unsigned int i = 0; i < K.m(); i += 7)
      if ((i + 1) % m != 0)
        {
          K.add(i, i + 1, 0.5);
          K.add(i + 1, i, 0.5);
        }
    K.compress(VectorOperation::add);
  }



  // x with K x = K e.
  LA::MPI::Vector
  solve(LinearSolver &solver, const LA::SparseMatrix &K, const IndexSet &all)
  {
    LA::MPI::Vector e(all, MPI_COMM_WORLD), b(e), x(e);
    e = 1.;
    K.vmult(b, e);
    solver.solve(x, b);
    return x;
  }



  void
  print_counts(const char *what, const LinearSolver &solver)
  {
    const auto [builds, updates] = solver.n_builds_and_updates();
    std::printf("  %s: %u built, %u updated\n", what, builds, updates);
  }



  // The solution of @p solver against that of a solver built anew for K.
  void
  compare_with_new_solver(const char             *method,
                          const char             *algebra,
                          LinearSolver           &solver,
                          const LA::SparseMatrix &K,
                          const IndexSet         &all,
                          const NearNullSpace    &modes)
  {
    LinearSolver fresh = grid_linear_solver(method, algebra);
    fresh.initialize(K, modes);
    LA::MPI::Vector error = solve(solver, K, all);
    error.add(-1., solve(fresh, K, all));
    std::printf("  the solution against a solver built anew: %s\n",
                error.linfty_norm() == 0. ? "the same bits" : "differs");
  }



  // A negative diagonal entry makes K indefinite: initialize() must refuse
  // it as a new factorization does, and factorize once it is undone.
  void
  check_indefinite_change(LinearSolver        &solver,
                          LA::SparseMatrix    &K,
                          const NearNullSpace &modes,
                          const unsigned int   row)
  {
    K.add(row, row, -100.);
    K.compress(VectorOperation::add);
    try
      {
        solver.initialize(K, modes);
        std::printf("  indefinite change factorized: wrong\n");
      }
    catch (const std::exception &error)
      {
        const std::string message = error.what();
        std::printf("  indefinite change refused: %s\n",
                    message.find("not positive definite") != std::string::npos ?
                      "yes" :
                      "no");
      }
    K.add(row, row, 100.);
    K.compress(VectorOperation::add);
    solver.initialize(K, modes);
    print_counts("undone and initialized", solver);
  }



  void
  check(const char *method, const char *algebra, const unsigned int m)
  {
    std::printf("%s (%s), %u x %u grid:\n", method, algebra, m, m);
    const IndexSet   all = grid_rows(m);
    LA::SparseMatrix K;
    grid_matrix(m, 1., K);
    const NearNullSpace modes = constant_modes(all);

    LinearSolver solver = grid_linear_solver(method, algebra);
    solver.initialize(K, modes);
    print_counts("first initialize()", solver);
    change_values(K, m);
    solver.initialize(K, modes);
    print_counts("values changed", solver);
    compare_with_new_solver(method, algebra, solver, K, all, modes);
    if (std::string(method) == "Cholesky")
      check_indefinite_change(solver, K, modes, m * m / 2);

    const NearNullSpace constants;
    grid_matrix(m + 1, 1., K);
    solver.initialize(K, constants);
    print_counts("new pattern", solver);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("Cholesky", "Trilinos", 300);
  check("MUMPS", "PETSc", 100);
  check("CG with AMG", "Trilinos", 100);
}
