// The test matrix of the factorization and linear solver tests: the
// five-point Laplacian of an m x m grid plus a shift of the diagonal, on one
// process, and a LinearSolver of a given method for it.
#ifndef vpcontact_tests_grid_matrix_h
#define vpcontact_tests_grid_matrix_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace VPContact
{
  /// The rows of the grid matrix of an m x m grid, all on this process.
  inline IndexSet
  grid_rows(const unsigned int m)
  {
    IndexSet all(m * m);
    all.add_range(0, m * m);
    return all;
  }



  /// The m^2 x m^2 matrix with diagonal 4 + @p shift and -1 for each grid
  /// neighbour: positive definite where shift > -4 + 4 cos(pi / (m + 1))
  /// (about -0.045 at m = 20), indefinite with a positive diagonal at
  /// shift = -1.
  inline void
  grid_matrix(const unsigned int m, const double shift, LA::SparseMatrix &K)
  {
    const unsigned int  n   = m * m;
    const IndexSet      all = grid_rows(m);
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


  /// The constants on the rows @p all, as AMG's near null space of the
  /// grid matrix (a scalar problem).
  inline NearNullSpace
  constant_modes(const IndexSet &all)
  {
    NearNullSpace modes;
    modes.modes.emplace_back(all, MPI_COMM_WORLD);
    modes.modes.back() = 1.;
    return modes;
  }



  /// A LinearSolver with Solver/Linear solver = @p method and Solver/Linear
  /// algebra = @p algebra.
  inline LinearSolver
  grid_linear_solver(const std::string &method,
                     const std::string &algebra = "Trilinos")
  {
    ParameterHandler prm;
    LinearSolver::declare_parameters(prm);
    prm.enter_subsection("Solver");
    prm.set("Linear algebra", algebra);
    prm.set("Linear solver", method);
    prm.leave_subsection();
    LinearSolver solver;
    solver.parse_parameters(prm);
    return solver;
  }
} // namespace VPContact

#endif
