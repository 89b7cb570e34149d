// The linear system of a step's displacement increment, on the displacement
// block of the degrees of freedom: matrix, right-hand side and the
// LinearSolver that solves it.
#ifndef vpcontact_displacement_system_h
#define vpcontact_displacement_system_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The displacement problem of a step, (E eps(du), eps(v)) = b(v), on the
   * displacement block [0, n_u) of the block numbering (see
   * Simulator::setup_dofs()). The simulator assembles K once per mesh (and
   * when the stick set changes) and b in every step; the LinearSolver,
   * chosen in the section "Solver", solves K du = b. A plain aggregate, as
   * the linear algebra members of step-40: the simulator's assembly and
   * solve functions fill and read it.
   */
  struct DisplacementSystem
  {
    /// The block's owned and relevant degrees of freedom.
    IndexSet owned;
    IndexSet relevant;
    /// The shape functions of a cell that belong to the displacement.
    std::vector<unsigned int> shape_functions;
    /// K and b; the solver's vector is the displacement block of the
    /// simulator's increment.
    LA::SparseMatrix matrix;
    LA::MPI::Vector  rhs;
    /// The rigid motions at the nodes, AMG's near null space: computed at
    /// the first build of AMG on a mesh and kept for the rebuilds after the
    /// stick set changes (empty with a factorization, and after a new mesh).
    NearNullSpace rigid_motions;
    /// Declared after the matrix, so destroyed before it: a factorization
    /// refers to the matrix.
    LinearSolver solver;
  };
} // namespace VPContact

#endif
