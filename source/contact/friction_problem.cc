// The Tresca friction problem: contact cells, the active-set update from the
// residual, statistics and the checkpointed state.
#include <vpcontact/contact/friction_problem.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <algorithm>
#include <cstdio>

namespace VPContact
{
  namespace
  {
    /**
     * The period L >= 2 with which the last fingerprints of @p prints run
     * through the same sets three times over (4 L entries, each equal to
     * the one L before it, and not all of a period equal), or 0. Coulomb's
     * bounds converge with the sets held, so a set that keeps coming back
     * on such a schedule is a cycle of sets and bounds together, not a
     * path to the solution.
     */
    unsigned int
    repeated_period(const std::vector<unsigned long long> &prints)
    {
      constexpr unsigned int repeats = 3, longest = 25;
      for (unsigned int period = 2;
           period <= longest && (repeats + 1) * period <= prints.size();
           ++period)
        {
          const auto end      = prints.end();
          const auto begin    = end - (repeats + 1) * period;
          bool       periodic = std::equal(begin + period, end, begin);
          periodic = periodic && std::any_of(end - period, end, [&](auto p) {
                       return p != *(end - 1);
                     });
          if (periodic)
            return period;
        }
      return 0;
    }
  } // namespace


  namespace
  {
    // One component of a nodal vector as a scalar field: the status (x
    // component of its vector), the contact pressure and the gap (x and y
    // components of theirs).
    template <int dim>
    class NodeScalarField : public DataPostprocessorScalar<dim>
    {
    public:
      NodeScalarField(const std::string &name, const unsigned int component)
        : DataPostprocessorScalar<dim>(name, update_values)
        , component(component)
      {}

      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>>                &computed) const override
      {
        for (unsigned int q = 0; q < computed.size(); ++q)
          computed[q](0) = inputs.solution_values[q](component);
      }

    private:
      const unsigned int component;
    };



    // The tangential traction of the contact nodes in the displacement
    // components of a vector (FrictionActiveSet::fill_output()): in 2D the
    // scalar sigma_tau along the node's tangent, in the x component; in 3D
    // the vector sigma_tau.
    template <int dim>
    class TractionField : public DataPostprocessor<dim>
    {
    public:
      void
      evaluate_vector_field(
        const DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<Vector<double>>                &computed) const override
      {
        for (unsigned int q = 0; q < computed.size(); ++q)
          for (unsigned int c = 0; c < computed[q].size(); ++c)
            computed[q](c) = inputs.solution_values[q](c);
      }

      std::vector<std::string>
      get_names() const override
      {
        return std::vector<std::string>(dim == 2 ? 1 : dim,
                                        "tangential_traction");
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<
          DataComponentInterpretation::DataComponentInterpretation>(
          dim == 2 ? 1 : dim,
          dim == 2 ? DataComponentInterpretation::component_is_scalar :
                     DataComponentInterpretation::component_is_part_of_vector);
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_values;
      }
    };

  } // namespace



  template <int dim>
  FrictionProblem<dim>::FrictionProblem(const TrescaFriction<dim> &friction,
                                        const MPI_Comm             communicator)
    : friction(friction)
    , communicator(communicator)
  {}



  template <int dim>
  void
  FrictionProblem<dim>::clear()
  {
    active_set = FrictionActiveSet<dim>();
    contact_cells.clear();
    last_iterations            = 0;
    largest_violation          = 0;
    largest_pressure_violation = 0;
    largest_gap_violation      = 0;
  }



  template <int dim>
  void
  FrictionProblem<dim>::setup(
    const DoFHandler<dim>              &dof_handler,
    const AffineConstraints<double>    &base_constraints,
    const std::set<types::boundary_id> &contact_boundary_ids,
    const IndexSet                     &locally_owned_dofs,
    const IndexSet                     &locally_relevant_dofs)
  {
    active_set.setup(dof_handler,
                     base_constraints,
                     contact_boundary_ids,
                     locally_relevant_dofs,
                     friction);

    // The multipliers are read at the contact nodes only, so the residual
    // is assembled only on the cells that hold one.
    contact_cells.clear();
    const IndexSet contact_dofs = active_set.node_dofs(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dof_indices(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dof_indices);
          if (std::any_of(dof_indices.begin(),
                          dof_indices.end(),
                          [&](const auto dof) {
                            return contact_dofs.is_element(dof);
                          }))
            contact_cells.push_back(cell);
        }
    residual.reinit(locally_owned_dofs, locally_relevant_dofs, communicator);
  }



  template <int dim>
  void
  FrictionProblem<dim>::add_constraints(AffineConstraints<double> &constraints,
                                        const LA::MPI::Vector     *previous,
                                        const bool with_stick) const
  {
    active_set.add_contact_constraints(constraints, previous);
    if (with_stick)
      active_set.add_stick_constraints(constraints);
  }



  template <int dim>
  void
  FrictionProblem<dim>::begin_step(const double time)
  {
    active_set.set_bounds(friction, time);
    last_iterations = 0;
    step_fingerprints.assign(1, active_set.fingerprint());
  }



  template <int dim>
  void
  FrictionProblem<dim>::add_slip_forces(
    const AffineConstraints<double> &constraints,
    LA::MPI::Vector                 &rhs) const
  {
    active_set.add_slip_forces(constraints, rhs);
  }



  template <int dim>
  void
  FrictionProblem<dim>::add_slip_stiffness(
    const AffineConstraints<double> &constraints,
    LA::SparseMatrix                &matrix)
  {
    active_set.add_slip_stiffness(constraints, matrix);
  }



  template <int dim>
  void
  FrictionProblem<dim>::update_slip_stiffness(
    const AffineConstraints<double> &constraints,
    LA::SparseMatrix                &matrix)
  {
    active_set.update_slip_stiffness(constraints, matrix);
  }



  template <int dim>
  typename FrictionActiveSet<dim>::Changes
  FrictionProblem<dim>::update(const LA::MPI::Vector &increment,
                               const LA::MPI::Vector &previous,
                               const double           youngs_modulus,
                               const LA::MPI::Vector &assembled_residual)
  {
    ++last_iterations;
    residual_exchange.copy(assembled_residual, residual);
    auto changes = active_set.update(residual,
                                     increment,
                                     previous,
                                     youngs_modulus,
                                     friction);
    // Sets that come back after they changed: the iteration cycles (the
    // semismooth Newton method converges only locally). With Coulomb's
    // law the bounds move between visits, so a set may come back on the
    // way to the solution: there it counts only once no bound moves, or
    // once the sets have run through the same period several times.
    const unsigned long long print = active_set.fingerprint();
    if (print != step_fingerprints.back() && changes.n_bounds_moved == 0)
      for (unsigned int k = step_fingerprints.size(); k-- > 0;)
        if (step_fingerprints[k] == print)
          {
            changes.cycle_length = step_fingerprints.size() - k;
            break;
          }
    step_fingerprints.push_back(print);
    if (changes.cycle_length == 0 && changes.n_bounds_moved > 0)
      changes.cycle_length = repeated_period(step_fingerprints);
    return changes;
  }



  template <int dim>
  const std::vector<typename FrictionProblem<dim>::CellIterator> &
  FrictionProblem<dim>::residual_cells() const
  {
    return contact_cells;
  }



  template <int dim>
  void
  FrictionProblem<dim>::set_motion_free_when_all_slip(const std::string &motion)
  {
    free_when_all_slip = motion;
  }



  template <int dim>
  const std::string &
  FrictionProblem<dim>::motion_free_when_all_slip() const
  {
    return free_when_all_slip;
  }



  template <int dim>
  bool
  FrictionProblem<dim>::keep_one_stick()
  {
    return active_set.keep_one_stick();
  }



  template <int dim>
  unsigned int
  FrictionProblem<dim>::n_stick_nodes() const
  {
    return active_set.count().first;
  }



  template <int dim>
  unsigned int
  FrictionProblem<dim>::n_slip_nodes() const
  {
    return active_set.count().second;
  }



  template <int dim>
  double
  FrictionProblem<dim>::max_bound() const
  {
    return active_set.max_bound();
  }



  template <int dim>
  unsigned int
  FrictionProblem<dim>::iterations() const
  {
    return last_iterations;
  }



  template <int dim>
  void
  FrictionProblem<dim>::add_statistics(Statistics  &statistics,
                                       std::string &line,
                                       const StepQuantities & /*quantities*/)
  {
    const auto [n_stick, n_slip] = active_set.count();
    const double utilisation     = active_set.max_utilisation();
    // Relative to the largest g; slip counts where |w_i| exceeds 1e-8 of
    // the largest tangential increment.
    const double violation = active_set.max_violation(1e-8);
    statistics.add_value("active_set_iterations", last_iterations);
    statistics.add_value("stick_nodes", n_stick);
    statistics.add_value("slip_nodes", n_slip);
    statistics.add_value("friction_utilisation", utilisation);
    statistics.add_value("friction_violation", violation);
    largest_violation = std::max(largest_violation, violation);
    char text[32];
    std::snprintf(text, sizeof(text), "%.4f", utilisation);
    line += "  stick/slip = " + std::to_string(n_stick) + "/"
            + std::to_string(n_slip) + "  max|sigma_t|/g = " + text;
    if (friction.unilateral())
      add_normal_statistics(statistics, line);
  }



  template <int dim>
  void
  FrictionProblem<dim>::add_normal_statistics(Statistics  &statistics,
                                              std::string &line)
  {
    // The lumped measures are lengths on a 2D body's boundary, areas on a
    // 3D one's.
    const auto        measures = active_set.normal_measures();
    const std::string measure  = (dim == 2 ? "length" : "area");
    statistics.add_value("contact_nodes", measures.n_contact);
    statistics.add_value("separated_nodes", measures.n_separated);
    statistics.add_value("contact_" + measure, measures.contact_measure);
    statistics.add_value("stick_" + measure, measures.stick_measure);
    statistics.add_value("max_contact_pressure", measures.max_pressure);
    statistics.add_value("normal_force", measures.normal_force);
    statistics.add_value("friction_force", measures.tangential_force);
    statistics.add_value("pressure_violation", measures.pressure_violation);
    statistics.add_value("gap_violation", measures.gap_violation);
    largest_pressure_violation
      = std::max(largest_pressure_violation, measures.pressure_violation);
    largest_gap_violation
      = std::max(largest_gap_violation, measures.gap_violation);
    char text[32];
    std::snprintf(text, sizeof(text), "%.4e", measures.max_pressure);
    line += "  contact/separated = " + std::to_string(measures.n_contact) + "/"
            + std::to_string(measures.n_separated) + "  max p = " + text;
  }



  template <int dim>
  std::string
  FrictionProblem<dim>::iteration_counts() const
  {
    return "  AS its = " + std::to_string(last_iterations);
  }



  template <int dim>
  std::string
  FrictionProblem<dim>::violation_summary() const
  {
    char violation[32];
    std::snprintf(violation, sizeof(violation), "%.1e", largest_violation);
    std::string text
      = std::string(friction.friction_law()
                        == TrescaFriction<dim>::FrictionLaw::coulomb ?
                      "Coulomb" :
                      "Tresca")
        + " conditions at every contact node and step: largest violation "
        + violation + " of max(g, |sigma nu|) (holds to 1e-8: "
        + (largest_violation < 1e-8 ? "yes" : "NO") + ")\n";
    if (friction.unilateral())
      {
        char pressure[32], gap[32];
        std::snprintf(pressure,
                      sizeof(pressure),
                      "%.1e",
                      largest_pressure_violation);
        std::snprintf(gap, sizeof(gap), "%.1e", largest_gap_violation);
        text += std::string("Signorini conditions at every contact node and "
                            "step: largest violation of the pressure ")
                + pressure + " of max(g, |sigma nu|) (holds to 1e-8: "
                + (largest_pressure_violation < 1e-8 ? "yes" : "NO")
                + "), of the gap " + gap + " m\n";
      }
    return text;
  }



  template <int dim>
  double
  FrictionProblem<dim>::max_violation() const
  {
    return largest_violation;
  }



  template <int dim>
  std::vector<NodalField<dim>>
  FrictionProblem<dim>::output_fields(const OwnedLayout &owned_layout) const
  {
    // Status (0 none, 1 stick, 2 slip) and tangential traction sigma_tau of
    // the contact nodes, in the displacement entries of a vector on every
    // degree of freedom.
    // With unilateral contact (3 separated), also the contact pressure
    // -sigma_nu and the gap, from one vector.
    std::vector<NodalField<dim>> fields(friction.unilateral() ? 4 : 2);
    for (auto &field : fields)
      owned_layout.make(field.values);
    active_set.fill_output(fields[0].values, fields[1].values);
    fields[0].postprocessor
      = std::make_shared<NodeScalarField<dim>>("contact_status", 0);
    fields[1].postprocessor = std::make_shared<TractionField<dim>>();
    if (friction.unilateral())
      {
        active_set.fill_normal_output(fields[2].values);
        fields[3].values = fields[2].values;
        fields[2].postprocessor
          = std::make_shared<NodeScalarField<dim>>("contact_pressure", 0);
        fields[3].postprocessor
          = std::make_shared<NodeScalarField<dim>>("gap", 1);
      }
    return fields;
  }



  template <int dim>
  void
  FrictionProblem<dim>::write_checkpoint(
    LA::MPI::Vector               &sets_owned,
    std::map<std::string, double> &counters) const
  {
    active_set.write_state(sets_owned);
    counters["max_friction_violation"] = largest_violation;
    if (friction.unilateral())
      {
        counters["max_pressure_violation"] = largest_pressure_violation;
        counters["max_gap_violation"]      = largest_gap_violation;
      }
  }



  template <int dim>
  void
  FrictionProblem<dim>::read_checkpoint(
    const LA::MPI::Vector & /*sets_owned*/,
    const LA::MPI::Vector                            &sets,
    const std::function<double(const std::string &)> &counter)
  {
    read_state(sets, counter, false);
  }



  template <int dim>
  void
  FrictionProblem<dim>::read_state(
    const LA::MPI::Vector                            &sets,
    const std::function<double(const std::string &)> &counter,
    const bool                                        interpolated)
  {
    active_set.read_state(sets, interpolated);
    largest_violation = counter("max_friction_violation");
    if (friction.unilateral())
      {
        largest_pressure_violation = counter("max_pressure_violation");
        largest_gap_violation      = counter("max_gap_violation");
      }
  }



  template <int dim>
  void
  FrictionProblem<dim>::read_transferred_state(
    const LA::MPI::Vector                            &sets_owned,
    const LA::MPI::Vector                            &sets,
    const std::function<double(const std::string &)> &counter)
  {
    (void)sets_owned;
    read_state(sets, counter, true);
  }



  template class FrictionProblem<2>;
  template class FrictionProblem<3>;
} // namespace VPContact
