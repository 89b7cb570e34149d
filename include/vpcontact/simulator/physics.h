// The interface the simulator speaks to its optional physics (the damage
// problem, the friction problem): statistics, the run's summary and the
// checkpointed state, so that the simulator loops over them instead of
// testing for each.
#ifndef vpcontact_physics_h
#define vpcontact_physics_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/postprocess/statistics.h>

#include <functional>
#include <map>
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

  /**
   * A physics object the simulator builds only when a scene needs it (as
   * ASPECT gives optional physics a handler and Lethe an AuxiliaryPhysics):
   * it owns its unknowns, sets, statistics and checkpointed state. How it
   * takes part in a step differs (the damage step runs beside the first
   * displacement solve, the friction iteration around every solve) and is
   * called by name; what every such object does at the end of a step, at the
   * end of a run and at a checkpoint is here.
   */
  class Physics
  {
  public:
    virtual ~Physics() = default;

    /// The step's columns of @p statistics and its part of the screen
    /// @p line.
    virtual void
    add_statistics(Statistics           &statistics,
                   std::string          &line,
                   const StepQuantities &quantities)
      = 0;

    /// The iteration count of the step for the screen line (which only
    /// runs that do not promise deterministic output print), or "".
    virtual std::string
    iteration_counts() const;

    /// The line of the run's summary that says how well the object's
    /// discrete conditions held over every step, with its newline.
    virtual std::string
    violation_summary() const = 0;

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
  };
} // namespace VPContact

#endif
