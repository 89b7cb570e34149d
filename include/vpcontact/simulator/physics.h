// The interface the simulator speaks to its optional physics (the damage
// problem, the friction problem): setup on a mesh, a step's work, the
// recovery space they offer, statistics, the run's summary and the
// checkpointed state, so that the simulator loops over them instead of
// testing for each.
#ifndef vpcontact_physics_h
#define vpcontact_physics_h

#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/fe/scalar_node_space.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/owned_layout.h>
#include <vpcontact/postprocess/statistics.h>
#include <vpcontact/simulator/simulator_access.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /// What the simulator measures in a step that a physics object reports
  /// as its own (in the manner of ASPECT's postprocessors' inputs).
  struct StepQuantities
  {
    /// The volume fraction where zeta < 1 at the quadrature points.
    double damaged_fraction = 0;
  };

  /// A nodal field a physics object adds to the output: values on every
  /// degree of freedom of the FESystem (as the solution has them) and the
  /// postprocessor that names the field and reads it from those values.
  template <int dim>
  struct NodalField
  {
    LA::MPI::Vector                               values;
    std::shared_ptr<const DataPostprocessor<dim>> postprocessor;
  };

  /**
   * A physics object the simulator builds only when a scene needs it (as
   * ASPECT gives optional physics a handler and Lethe an AuxiliaryPhysics):
   * it owns its unknowns, sets, statistics and checkpointed state. The
   * simulator calls every object it built through this interface: on a new
   * mesh, in a step, at its end, at the end of a run and at a checkpoint.
   * An object that has no part in one of these keeps the default, which
   * does nothing. (The friction problem takes part in the displacement
   * problem's solves, which own it and call it there.)
   */
  template <int dim>
  class Physics
  {
  public:
    virtual ~Physics() = default;

    /// On a new mesh of @p simulator, after the displacement problem's
    /// setup: the object's own setup, and its block of u_0 in
    /// @p solution.
    virtual void
    setup_on_mesh(const SimulatorAccess<dim> &simulator,
                  LA::MPI::BlockVector       &solution);

    /// The scalar node space of the object's unknowns, if it has one: the
    /// error estimate recovers its fields there.
    virtual std::optional<ScalarNodeSpace<dim>>
    node_space() const;

    /// Whether solve_step() has work (then the simulator runs it beside
    /// the first displacement solve of the step).
    virtual bool
    solves_in_step() const;

    /**
     * The object's unknowns of step @p n from the data of step n - 1 only:
     * its block of @p solution (u_{n-1}) and what the assembly stored in
     * @p history. They stay in the object until store(), since the stress
     * update still reads step n - 1's.
     */
    virtual void
    solve_step(const unsigned int          n,
               const LA::MPI::BlockVector &solution,
               const StressHistory<dim>   &history);

    /// After the stress update of step @p n: the object's unknowns into
    /// its block of @p solution.
    virtual void
    store(const unsigned int n, LA::MPI::BlockVector &solution);

    /// Whether the object's columns of statistics.csv come before those of
    /// the errors against exact and reference solutions (the damage's do,
    /// the friction's come last).
    virtual bool
    reports_before_errors() const;

    /// The step's columns of @p statistics and its part of the screen
    /// @p line.
    virtual void
    add_statistics(Statistics           &statistics,
                   std::string          &line,
                   const StepQuantities &quantities)
      = 0;

    /// The names of the object's scalar components of the solution in the
    /// output fields, in the FESystem's order (none by default).
    virtual std::vector<std::string>
    solution_field_names() const;

    /// The object's nodal fields for the output of this step, with values
    /// on this rank's degrees of freedom, made by @p owned_layout (none by
    /// default).
    virtual std::vector<NodalField<dim>>
    output_fields(const OwnedLayout &owned_layout) const;

    /// The iteration count of the step for the screen line (which only
    /// runs that do not promise deterministic output print), or "".
    virtual std::string
    iteration_counts() const;

    /// The line of the run's summary that says how well the object's
    /// discrete conditions held over every step, with its newline.
    virtual std::string
    violation_summary() const = 0;

    /// The line of the run's summary that says how much work the object's
    /// own solves did and, on several ranks, how evenly they spread it over
    /// the ranks, with its newline, or "" (the default). A collective call.
    virtual std::string
    work_summary() const;

    /// The object's sets into its degrees of freedom of @p sets_owned, and
    /// the counters a resumed run needs into @p counters.
    virtual void
    write_checkpoint(LA::MPI::Vector               &sets_owned,
                     std::map<std::string, double> &counters) const = 0;

    /// The state write_checkpoint() saved, in @p sets_owned and in its
    /// ghosted copy @p sets; @p counter reads a counter.
    virtual void
    read_checkpoint(const LA::MPI::Vector &sets_owned,
                    const LA::MPI::Vector &sets,
                    const std::function<double(const std::string &)> &counter)
      = 0;

    /**
     * After the mesh changed during the run (setup_on_mesh() done on the
     * new mesh): the state write_checkpoint() wrote on the old mesh,
     * interpolated onto the new one. A node between nodes of different
     * sets holds no valid set; it starts where the object's iteration
     * starts a node it knows nothing of. The default reads it as a
     * checkpoint.
     */
    virtual void
    read_transferred_state(
      const LA::MPI::Vector                            &sets_owned,
      const LA::MPI::Vector                            &sets,
      const std::function<double(const std::string &)> &counter);
  };
} // namespace VPContact

#endif
