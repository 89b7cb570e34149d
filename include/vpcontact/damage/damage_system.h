// The linear algebra of the damage obstacle problem on the damage block of
// the FESystem's degrees of freedom: the block's index sets, the matrix
// M_L/k + kappa A with its preconditioner, and the CG solve with nodes held
// at bounds.
#ifndef vpcontact_damage_system_h
#define vpcontact_damage_system_h

#include <vpcontact/damage/damage_obstacle_snes.h>
#include <vpcontact/damage/damage_region_solver.h>
#include <vpcontact/damage/support_product.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/spd_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <utility>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The damage zeta is the last component of the simulator's FESystem,
   * whose degrees of freedom are numbered by blocks (as in step-32 and
   * step-55): the damage is the block [n_u, n), a third (2D) or a quarter
   * (3D) of all of them. The damage problem works on that block alone, in
   * its own index range [0, n - n_u) (the index of a degree of freedom
   * less n_u, which get_view() gives): a scalar matrix, its
   * preconditioner, and vectors of the block's size, so that no
   * displacement row is dragged through its products and AMG levels.
   * gather() and scatter() copy the block's owned entries out of and into
   * a vector on all degrees of freedom, where they follow the displacement
   * block's; the solution itself stays in the FESystem.
   *
   * "Compact" below means an index or vector of the damage block.
   *
   * The preconditioner of the CG solves is the entry "Damage
   * preconditioner" of section "Solver" (declared here, since this class
   * is its only user).
   */
  template <int dim>
  class DamageSystem
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// The section "Solver"'s damage entries; @p linear_algebra is the
    /// package of Solver/Linear algebra, which LinearSolver parses.
    void
    parse_parameters(ParameterHandler &prm, const LinearAlgebra linear_algebra);

    /**
     * Take the damage block (component @p component of the FESystem of
     * @p dof_handler, its last, numbered by blocks) and build its hanging
     * node constraints and the sparsity pattern of the compact system. Releases
     * the preconditioner of an earlier mesh first.
     */
    void
    reinit(const DoFHandler<dim> &dof_handler,
           const unsigned int     component,
           const IndexSet        &locally_owned_dofs,
           const IndexSet        &locally_relevant_dofs,
           const MPI_Comm         communicator);

    /// Locally owned and locally relevant compact indices.
    const IndexSet &
    owned() const;
    const IndexSet &
    relevant() const;

    /**
     * The shape functions of the FESystem that belong to the damage, in the
     * order in which dof_indices() lists their compact indices.
     */
    const std::vector<unsigned int> &
    shape_functions() const;

    /// The compact indices of a locally owned cell's damage shape functions.
    void
    dof_indices(const typename DoFHandler<dim>::active_cell_iterator &cell,
                std::vector<types::global_dof_index> &indices) const;

    /// Hanging node constraints in the compact numbering.
    const AffineConstraints<double> &
    hanging_node_constraints() const;

    /**
     * Set the hanging nodes of @p owned_vector from their parents. A
     * collective call, which does nothing on a mesh without hanging nodes:
     * deal.II's AffineConstraints::distribute() builds a ghosted copy of
     * the vector and an import for it on every call, even with no
     * constraint to apply, and a run makes hundreds of damage solves.
     */
    void
    distribute_hanging_nodes(LA::MPI::Vector &owned_vector) const;

    /// The local positions (see local_position()) of the owned hanging
    /// nodes, which every solve holds.
    const std::vector<unsigned int> &
    hanging_node_positions() const;

    /// The position of an owned compact index in the local vector entries.
    unsigned int
    local_position(const types::global_dof_index compact_index) const;

    /// Owned damage entries: FESystem vector -> compact vector.
    void
    gather(const LA::MPI::Vector &full, LA::MPI::Vector &compact) const;

    /// Owned damage entries: compact vector -> FESystem vector (the
    /// displacement entries of @p full are left alone).
    void
    scatter(const LA::MPI::Vector &compact, LA::MPI::Vector &full) const;

    /// The matrix, for assembly (its sparsity pattern is set by reinit()).
    LA::SparseMatrix &
    matrix();

    /**
     * Take the assembled matrix into the rows that the products and the
     * region solver read (OwnedRows) and build the preconditioner. Where
     * no library solver reads the Trilinos matrix (the region solver,
     * without SNES VI) it is released: the rows are then the only copy of
     * K, and matrix() is valid again after the next reinit().
     */
    void
    initialize_preconditioner();

    /// y = K x, at the cost of the entries of x that are not zero (see
    /// SupportProduct): for the changes of a damage solve, which vanish
    /// where the damage stays at a bound.
    void
    vmult_on_support(LA::MPI::Vector &y, const LA::MPI::Vector &x);

    /// vmult_on_support() on the owned positions @p rows alone (see
    /// SupportProduct::vmult_on()).
    void
    vmult_on_rows(LA::MPI::Vector                 &y,
                  const LA::MPI::Vector           &x,
                  const std::vector<unsigned int> &rows);

    /// The product, for the neighbours of a node in the matrix graph and
    /// the front of the damage bounds.
    const SupportProduct &
    support() const;
    SupportProduct &
    support();

    /// A new time step: the region solver builds its region again from
    /// the free set of the step's first solve.
    void
    begin_step();

    /**
     * Solve K_FF x_F = b_F on the free nodes, x = 0 on the nodes listed in
     * @p held (local positions, see local_position()), by CG over the free
     * nodes (DamageRegionSolver) or an SpdSolver that holds the others, as
     * Solver/Damage preconditioner says. @p b and @p x must be zero on the held
     * nodes (@p x is the start vector). Stops at a residual of @p tolerance
     * times |b|; throws a message naming the Solver parameters otherwise.
     * Returns the number of CG iterations.
     */
    unsigned int
    solve(const LA::MPI::Vector           &b,
          LA::MPI::Vector                 &x,
          const std::vector<unsigned int> &held,
          const double                     tolerance,
          const unsigned int               max_iterations);

    /// Whether solve_free() can be used: the damage preconditioner is one
    /// of the region solver's.
    bool
    solves_on_free_nodes() const;

    /// solve() with the free nodes given instead of the held ones (see
    /// DamageRegionSolver::solve_free()); only if solves_on_free_nodes().
    unsigned int
    solve_free(const LA::MPI::Vector           &b,
               LA::MPI::Vector                 &x,
               const std::vector<unsigned int> &free,
               const double                     tolerance,
               const unsigned int               max_iterations);

    /**
     * The work of this rank's damage solves in this process so far: the sum
     * over the solves of solve() and solve_free() of the rank's free nodes
     * times the solve's CG iterations. Each iteration costs about as much
     * per free node, so the largest of these over the ranks against their
     * mean says how much the ranks lose by waiting for the busiest one in
     * the solves' reductions.
     */
    double
    solve_work() const;

    /// Whether Solver/Damage obstacle solver = SNES VI: the bounds are then
    /// found by solve_obstacle() instead of the caller's active set.
    bool
    solves_obstacle_whole() const;

    /**
     * The obstacle problem K zeta = b with 0 <= zeta <= 1 by PETSc's SNES
     * VI (see DamageObstacleSnes): @p zeta holds zeta_{n-1} and gets
     * zeta_n. Returns the Newton steps.
     */
    unsigned int
    solve_obstacle(const LA::MPI::Vector &b,
                   LA::MPI::Vector       &zeta,
                   const double           tolerance,
                   const unsigned int     max_iterations,
                   const unsigned int     max_linear_iterations);


  private:
    /// The message of a damage CG that did not reach @p target, the
    /// relative @p tolerance of |b| within @p max_iterations.
    static void
    throw_no_convergence(const SolverControl::NoConvergence &e,
                         const double                        target,
                         const double                        tolerance,
                         const unsigned int                  max_iterations);

    /// The damage block of the FESystem's numbering: the index sets,
    /// block_start, owned_offset and cell_dofs.
    void
    take_block(const DoFHandler<dim> &dof_handler,
               const IndexSet        &locally_owned_dofs,
               const IndexSet        &locally_relevant_dofs);

    types::global_dof_index
    count_damage_dofs(const DoFHandler<dim> &dof_handler) const;

    void
    make_hanging_node_constraints(const DoFHandler<dim> &dof_handler,
                                  const IndexSet        &locally_relevant_dofs);

    IndexSet compact_owned;
    IndexSet compact_relevant;
    IndexSet damage_dofs;
    /// The first damage degree of freedom of the FESystem (the block's
    /// offset), and the position of this rank's first owned one in the
    /// local entries of an owned FESystem vector.
    types::global_dof_index   block_start  = 0;
    std::size_t               owned_offset = 0;
    std::vector<unsigned int> damage_shape_functions;
    /// The compact indices of each locally owned cell, by active cell index.
    std::vector<types::global_dof_index> cell_dofs;
    AffineConstraints<double>            constraints;
    std::vector<unsigned int>            hanging_positions;
    /// Whether any rank has a hanging node.
    bool has_hanging_nodes = false;

    /// Solver/Damage preconditioner, and the package of Solver/Linear
    /// algebra.
    SpdMethod                  method  = SpdMethod::cg_incomplete_cholesky;
    LinearAlgebra              package = LinearAlgebra::trilinos;
    LA::SparseMatrix           system_matrix;
    OwnedRows                  matrix_rows;
    std::unique_ptr<SpdSolver> solver;
    /// The program's own solver on a region around the free nodes, for the
    /// first two choices of Solver/Damage preconditioner.
    bool                               use_region_solver = true;
    DamageRegionSolver::Preconditioner region_kind
      = DamageRegionSolver::Preconditioner::diagonal;
    DamageRegionSolver region_solver;
    SupportProduct     support_product;
    /// See solve_work().
    double work_of_solves = 0.;
    /// Solver/Damage obstacle solver = SNES VI, and its solver.
    bool                                use_snes_vi = false;
    std::unique_ptr<DamageObstacleSnes> obstacle_snes;
  };
} // namespace VPContact

#endif
