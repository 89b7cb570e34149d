// The damage problem, step 4 of the scheme: the damage block of the solution,
// its lumped mass, matrix, load, the bounds 0 <= zeta <= 1 and their active
// set, and what a run reports of them. Built only in scenes with damage.
#ifndef vpcontact_damage_problem_h
#define vpcontact_damage_problem_h

#include <vpcontact/damage/damage_bounds.h>
#include <vpcontact/damage/damage_model.h>
#include <vpcontact/damage/damage_system.h>
#include <vpcontact/damage/damage_work_set.h>
#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/fe/scalar_node_space.h>
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>
#include <vpcontact/postprocess/statistics.h>
#include <vpcontact/simulator/physics.h>
#include <vpcontact/simulator/time_discretization.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The damage problem of the paper's scheme (14), step 4: find zeta_n in
   * [0, 1] with
   *   (M_L/k + kappa A) zeta_n = M_L zeta_{n-1}/k + (phi_{n-1}, psi)
   * on the free nodes (M_L the lumped mass, A the stiffness of the
   * Laplacian), by the primal-dual active set of the bounds around the
   * linear solves of DamageSystem, or whole by SNES VI. It owns everything
   * of the damage: the compact damage numbering and its matrix
   * (DamageSystem), the active sets (DamageBounds), the vectors of a step,
   * the lumped mass per cell, and its statistics. The simulator hands it
   * the solution (whose damage block it reads and writes) and the stress
   * history (whose damage source it integrates).
   *
   * The implementation: damage_problem.cc (setup, initial damage, assembly),
   * damage_problem_solve.cc (the active set, storing zeta_n, statistics,
   * checkpoints).
   */
  template <int dim>
  class DamageProblem : public Physics<dim>
  {
  public:
    /// The entries of the damage solvers (DamageSystem, section Solver).
    static void
    declare_parameters(ParameterHandler &prm);

    DamageProblem(ParameterHandler         &prm,
                  const DamageModel<dim>   &model,
                  const TimeDiscretization &time,
                  const LinearSolver       &linear_solver,
                  const std::string        &output_directory,
                  TimerOutput              &timer,
                  const MPI_Comm            communicator);

    /**
     * Once per mesh: the damage block's index sets, vectors, lumped mass,
     * bounds, the matrix and its preconditioner, and zeta_0 interpolated
     * into the damage block (block 1) of @p solution_owned. @p dof_handler and
     * @p quadrature (the rule of the stress history) must outlive the next
     * setup().
     */
    void
    setup(const DoFHandler<dim> &dof_handler,
          const Quadrature<dim> &quadrature,
          const IndexSet        &locally_owned_dofs,
          const IndexSet        &locally_relevant_dofs,
          LA::MPI::BlockVector  &solution_owned);

    /// setup() on the simulator's mesh, element and degrees of freedom.
    void
    setup_on_mesh(const SimulatorAccess<dim> &simulator,
                  LA::MPI::BlockVector       &solution_owned) override;

    /// True: the damage step of every step.
    bool
    solves_in_step() const override;

    /// True: the damage columns lead the step's statistics.
    bool
    reports_before_errors() const override;

    /**
     * Step 4 of step @p n: zeta_n from zeta_{n-1} (the damage block of
     * @p solution_owned) and the source phi_{n-1} stored in @p history.
     * zeta_n stays here until store().
     */
    void
    solve_step(const unsigned int          n,
               const LA::MPI::BlockVector &solution_owned,
               const StressHistory<dim>   &history) override;

    /// zeta_n clipped onto [0, 1] (by the solver tolerance) into the
    /// damage block of @p solution_owned.
    void
    store(const unsigned int n, LA::MPI::BlockVector &solution_owned) override;

    /// The step's damage columns of @p statistics (the damaged volume
    /// fraction from @p quantities) and its part of the screen @p line.
    void
    add_statistics(Statistics           &statistics,
                   std::string          &line,
                   const StepQuantities &quantities) override;

    /// The largest violation of the bounds over the run, which must be
    /// exactly 0.
    std::string
    violation_summary() const override;

    /// The damage solves' work (DamageSystem::solve_work()); on several
    /// ranks the largest against the mean, and what that leaves of the
    /// ranks' gain.
    std::string
    work_summary() const override;

    /// {"damage"}: zeta's name in the output fields.
    std::vector<std::string>
    solution_field_names() const override;

    /// The largest violation of the bounds so far (exactly 0 expected).
    double
    max_violation() const;

    /// The damage block as a scalar node space (for the error estimate's
    /// recovery), valid until the next setup().
    std::optional<ScalarNodeSpace<dim>>
    node_space() const override;

    /// The active sets into the damage entries of @p sets_owned (on all
    /// degrees of freedom), and the counters a resumed run needs.
    void
    write_checkpoint(LA::MPI::Vector               &sets_owned,
                     std::map<std::string, double> &counters) const override;

    /// The state write_checkpoint() saved (read from @p sets_owned);
    /// @p counter reads a counter.
    void
    read_checkpoint(
      const LA::MPI::Vector                            &sets_owned,
      const LA::MPI::Vector                            &sets,
      const std::function<double(const std::string &)> &counter) override;

    /// As read_checkpoint(), with the sets interpolated onto a new mesh:
    /// a node with no valid set starts in the free set.
    void
    read_transferred_state(
      const LA::MPI::Vector                            &sets_owned,
      const LA::MPI::Vector                            &sets,
      const std::function<double(const std::string &)> &counter) override;

  private:
    /// read_checkpoint() and read_transferred_state().
    void
    read_state(const LA::MPI::Vector                            &sets_owned,
               const std::function<double(const std::string &)> &counter,
               const bool                                        interpolated);

    // damage_problem.cc
    void
    setup_mass_and_bounds();
    void
    store_cell_mass(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const std::vector<types::global_dof_index> &dof_indices,
                    const Vector<double>                       &cell_mass);
    void
    interpolate_initial_damage(LA::MPI::BlockVector &solution_owned);
    std::pair<double, double>
    range(const LA::MPI::Vector &v) const;
    void
    assemble_matrix();
    void
    assemble_load(const StressHistory<dim> &history);

    // damage_problem_solve.cc
    void
    solve_by_active_set(const unsigned int n);
    bool
    find_sets_fast(const LA::MPI::Vector &step_rhs);
    unsigned int
    solve_with_sets(const LA::MPI::Vector &step_rhs, const double tolerance);
    /// The work set of the step's solves after its first decision, and the
    /// vectors outside it (see DamageWorkSet); false, and nothing built,
    /// where a quarter of the nodes or more move.
    bool
    start_work_set(const LA::MPI::Vector &step_rhs);
    /// solve_with_sets() with its passes over the work set alone.
    unsigned int
    solve_on_work_set(const LA::MPI::Vector &step_rhs, const double tolerance);
    /// @p ghosted = @p owned on the work set (one rank) or everywhere.
    void
    copy_on_work_set(const LA::MPI::Vector &owned,
                     GhostExchange         &exchange,
                     LA::MPI::Vector       &ghosted) const;

    const DamageModel<dim>   &model;
    const TimeDiscretization &time;
    const LinearSolver       &linear_solver;
    const std::string         output_directory;
    TimerOutput              &timer;
    const MPI_Comm            communicator;
    const DoFHandler<dim>    *dof_handler = nullptr;
    const Quadrature<dim>    *quadrature  = nullptr;

    /// The linear algebra on the damage degrees of freedom alone, and the
    /// active sets of the bounds; the vectors below are in its compact
    /// numbering.
    DamageSystem<dim> system;
    DamageBounds      bounds;
    /// zeta_{n-1} and zeta (owned), and a ghosted copy of zeta.
    LA::MPI::Vector old_damage;
    LA::MPI::Vector damage_owned;
    LA::MPI::Vector damage;
    /// zeta - zeta_{n-1}, the unknown of the solves, and their right-hand
    /// side (owned).
    LA::MPI::Vector change;
    LA::MPI::Vector solve_rhs;
    /// The nodes held in a solve (owned positions) and the change that puts
    /// the nodes at a bound there (owned): members, since a fresh vector of
    /// the size of the mesh in every solve costs its page faults.
    std::vector<unsigned int> held;
    LA::MPI::Vector           bound_change;
    /// The nodes the solves of the step can change, and of a solve on them
    /// the free nodes and those that changed set (owned positions).
    DamageWorkSet             work;
    std::vector<unsigned int> free_positions;
    std::vector<unsigned int> changed_positions;
    bool                      serial_layout = true;
    /// b = M_L zeta_{n-1}/k + (phi_{n-1}, psi): as assembled (with ghost
    /// entries) and owned.
    LA::MPI::Vector load_assembly;
    LA::MPI::Vector load;
    /// The multipliers b - K zeta: owned and ghosted.
    LA::MPI::Vector residual_owned;
    LA::MPI::Vector residual;
    LA::MPI::Vector lumped_mass;
    /// The copies into the ghosted damage and residual, with their imports
    /// kept (see GhostExchange): several per damage solve.
    GhostExchange damage_exchange;
    GhostExchange residual_exchange;
    /// For each locally owned cell (by active cell index), per damage shape
    /// function: its vertex-rule mass int_K psi_a, and the position of its
    /// node in the local storage of the ghosted vector damage. Set once per
    /// mesh by setup_mass_and_bounds(), read by the load of every step,
    /// which then needs no FEValues and no index lookups.
    std::vector<double>       cell_mass;
    std::vector<unsigned int> cell_positions;
    /// The same nodes' positions in the owned vector load, for the cells
    /// whose damage nodes are all owned and not hanging (plain_cells, whose
    /// load goes there directly); the other cells' entries are not read.
    std::vector<int> cell_owned;
    /// The locally owned cells, split as above: the active cell indices of
    /// those whose load goes into the owned vector directly, and the
    /// others, whose load goes through the constraints; and whether the
    /// others exist on any rank (else the load needs no assembly vector).
    std::vector<unsigned int>                                   plain_cells;
    std::vector<typename DoFHandler<dim>::active_cell_iterator> other_cells;
    bool load_through_assembly = true;

    unsigned int last_iterations = 0;
    /// How many whole rings of nodes the front of the upper bound moved in
    /// the previous step (DamageBounds::rings_moved()): the next step frees
    /// as many ahead of it.
    unsigned int rings_ahead       = 0;
    double       last_clip         = 0;
    double       largest_violation = 0;
  };
} // namespace VPContact

#endif
