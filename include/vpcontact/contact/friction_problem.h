// The contact problem on the contact boundary: its active set of contact,
// stick and slip, the residual that gives the multipliers, and what a run
// reports of it. Built in scenes with friction or unilateral contact.
#ifndef vpcontact_friction_problem_h
#define vpcontact_friction_problem_h

#include <vpcontact/contact/friction_active_set.h>
#include <vpcontact/contact/tresca_friction.h>
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/postprocess/statistics.h>
#include <vpcontact/simulator/physics.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Tresca or Coulomb friction with bilateral or unilateral contact,
   * solved by the primal-dual active set of step-41/42 around the
   * displacement solves: the contact, stick and slip sets
   * (FrictionActiveSet), the cells that hold a contact node (where the
   * residual r = b - A(du) is assembled: at a contact node its normal part
   * is the contact pressure, its tangential part the friction
   * multiplier), and the iteration counts and
   * violations a run reports. The DisplacementProblem owns it: it calls
   * begin_step(), then, after each solve, assembles the residual on
   * residual_cells() and calls update() until no node changes set.
   */
  template <int dim>
  class FrictionProblem : public Physics<dim>
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    FrictionProblem(const TrescaFriction<dim> &friction,
                    const MPI_Comm             communicator);

    /**
     * On a new mesh: the contact nodes from @p base_constraints (without
     * friction, closed), all in the stick set, and the contact cells.
     */
    void
    setup(const DoFHandler<dim>              &dof_handler,
          const AffineConstraints<double>    &base_constraints,
          const std::set<types::boundary_id> &contact_boundary_ids,
          const IndexSet                     &locally_owned_dofs,
          const IndexSet                     &locally_relevant_dofs);

    /// Forget the sets of an earlier mesh and the counters of a run.
    void
    clear();

    /// The normal constraints of the nodes in contact (unilateral, from
    /// the ghosted displacement @p previous of the last step; nullptr:
    /// zero) and, @p with_stick, the stick nodes' tangential constraints.
    void
    add_constraints(AffineConstraints<double> &constraints,
                    const LA::MPI::Vector     *previous,
                    const bool                 with_stick) const;

    /// The friction bounds at @p time; no iteration yet.
    void
    begin_step(const double time);

    /// The slip nodes' forces -m g n into @p rhs.
    void
    add_slip_forces(const AffineConstraints<double> &constraints,
                    LA::MPI::Vector                 &rhs) const;

    /// The slip nodes' stiffness (3D) into @p matrix, before compress().
    void
    add_slip_stiffness(const AffineConstraints<double> &constraints,
                       LA::SparseMatrix                &matrix);

    /// The change of the slip nodes' stiffness since the matrix was last
    /// given it, after an update() that changed no set; compresses it.
    void
    update_slip_stiffness(const AffineConstraints<double> &constraints,
                          LA::SparseMatrix                &matrix);

    /// The locally owned cells with a contact node: where update() needs
    /// the residual.
    const std::vector<CellIterator> &
    residual_cells() const;

    /**
     * One active-set iteration after a solve: the multipliers from the
     * residual r = b - A(du), which @p assembled_residual holds on the
     * contact nodes (assembled on residual_cells() and compressed), and the
     * next sets.
     */
    typename FrictionActiveSet<dim>::Changes
    update(const LA::MPI::Vector &increment,
           const LA::MPI::Vector &previous,
           const double           youngs_modulus,
           const LA::MPI::Vector &assembled_residual);

    /**
     * Record what the constraints without any stick node leave free (a
     * rigid motion, in words; empty if they hold the body): the motion the
     * body is free to make when every contact node slips.
     */
    void
    set_motion_free_when_all_slip(const std::string &motion);

    /// The motion set_motion_free_when_all_slip() recorded.
    const std::string &
    motion_free_when_all_slip() const;

    /// Put the slip node nearest to sticking (smallest |lambda + c w| - g)
    /// back into the stick set; false if there is no slip node.
    bool
    keep_one_stick();

    /// The number of stick nodes (all ranks).
    unsigned int
    n_stick_nodes() const;

    /// The number of slip nodes (all ranks).
    unsigned int
    n_slip_nodes() const;

    /// The largest friction bound at the contact nodes in this step (all
    /// ranks).
    double
    max_bound() const;

    /// The iterations of the current step.
    unsigned int
    iterations() const;

    /// The step's friction columns of @p statistics and its part of the
    /// screen @p line.
    void
    add_statistics(Statistics           &statistics,
                   std::string          &line,
                   const StepQuantities &quantities) override;

    /// "  AS its = N": the active-set iterations of the step.
    std::string
    iteration_counts() const override;

    /// The largest violation of the Tresca conditions over the run.
    std::string
    violation_summary() const override;

    /// The largest violation of the Tresca conditions so far (of max g).
    double
    max_violation() const;

    /// The contact nodes' status and tangential traction, as output fields.
    std::vector<NodalField<dim>>
    output_fields(const OwnedLayout &owned_layout) const override;

    /// The sets into @p sets_owned and the counters a resumed run needs.
    void
    write_checkpoint(LA::MPI::Vector               &sets_owned,
                     std::map<std::string, double> &counters) const override;

    /// The state write_checkpoint() saved (read from the ghosted @p sets).
    void
    read_checkpoint(
      const LA::MPI::Vector                            &sets_owned,
      const LA::MPI::Vector                            &sets,
      const std::function<double(const std::string &)> &counter) override;

    /// As read_checkpoint(), with the sets interpolated onto a new mesh:
    /// a node with no valid set starts in the stick set.
    void
    read_transferred_state(
      const LA::MPI::Vector                            &sets_owned,
      const LA::MPI::Vector                            &sets,
      const std::function<double(const std::string &)> &counter) override;

  private:
    /// read_checkpoint() and read_transferred_state().
    void
    read_state(const LA::MPI::Vector                            &sets,
               const std::function<double(const std::string &)> &counter,
               const bool                                        interpolated);

    const TrescaFriction<dim> &friction;
    const MPI_Comm             communicator;
    FrictionActiveSet<dim>     active_set;
    /// The locally owned cells with a contact node, where r is assembled.
    std::vector<CellIterator> contact_cells;
    /// A ghosted copy of r.
    LA::MPI::Vector residual;
    /// Copies the assembled residual into the ghosted one with an import
    /// built once: deal.II's assignment builds a new one at every call,
    /// which walks every index of both layouts.
    GhostExchange residual_exchange;
    /// The fingerprints of the sets at the start of the step and after
    /// each update(), to find a cycle.
    std::vector<unsigned long long> step_fingerprints;
    unsigned int                    last_iterations            = 0;
    double                          largest_violation          = 0;
    double                          largest_pressure_violation = 0;
    double                          largest_gap_violation      = 0;

    /// Unilateral contact: the step's columns of the contact and
    /// separation sets and its part of the screen @p line.
    void
    add_normal_statistics(Statistics &statistics, std::string &line);
    std::string free_when_all_slip;
  };
} // namespace VPContact

#endif
