// The simulator's adaptation of the mesh during a run: flags from the error
// indicators of the step, the state carried to the new mesh, and the setup
// of every physics object on it (see doc/adaptivity.md).
#include <vpcontact/app/exit_agreement.h>
#include <vpcontact/refinement/mesh_transfer.h>
#include <vpcontact/simulator/simulator.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>

#include <optional>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::setup_on_mesh(const std::function<void()> &after_dofs)
  {
    // The degrees of freedom, the quadrature points, the physics objects
    // and the estimator's recovery space on the current mesh. The estimate
    // recovers its fields on a physics object's scalar node space (the
    // damage block) where there is one, else on a space of its own.
    setup_dofs();
    if (after_dofs)
      after_dofs();
    displacement_problem.setup_stress_history();
    std::optional<ScalarNodeSpace<dim>> nodes;
    for (Physics<dim> *object : physics)
      {
        object->setup_on_mesh(access(), displacement_problem.solution_blocks());
        if (!nodes)
          nodes = object->node_space();
      }
    displacement_problem.update_ghosted_solution();
    if (error_estimator.is_active())
      error_estimator.setup(*mesh,
                            displacement_problem.cells(),
                            displacement_problem.kinematics(),
                            displacement_problem.history(),
                            nodes ? &*nodes : nullptr);
  }



  template <int dim>
  void
  Simulator<dim>::adapt_mesh(const unsigned int n)
  {
    // The cells of step n's largest indicators are refined, those of the
    // smallest coarsened (MeshRefinement); nothing to do if no cell is
    // flagged. The timer splits the cost: marking, transfer (with p4est's
    // repartitioning), and the setup on the new mesh.
    TimerOutput::Scope t(computing_timer, "Mesh adaptation");
    const unsigned int cells_before = mesh->n_global_active_cells();
    {
      TimerOutput::Scope m(computing_timer, "Mesh adaptation: marking");
      if (!convergence_study.refinement().flag_for_adaptation(
            *mesh,
            error_estimator.last_step_indicators(),
            displacement_problem.boundaries().contact_boundary_ids()))
        return;
    }
    change_mesh(n);
    pcout << "  mesh adapted after step " << n << ": " << cells_before << " -> "
          << mesh->n_global_active_cells() << " cells, " << dof_handler.n_dofs()
          << " dofs" << std::endl;
  }



  template <int dim>
  bool
  Simulator<dim>::adapt_initial_mesh()
  {
    // The initial state's indicators mark the cells; the new mesh gets the
    // initial state computed anew rather than transferred, as if the run
    // had started on it. The estimate of this mesh's step 0 is left out of
    // the run's largest estimate: the estimator's setup on the new mesh
    // starts it again.
    if (!error_estimator.estimates_step(0, time_discretization.n_steps()))
      return false;
    estimate_error(0);
    TimerOutput::Scope t(computing_timer, "Mesh adaptation");
    const double       largest = Utilities::MPI::max(
      double(error_estimator.last_step_indicators().linfty_norm()),
      mpi_communicator);
    if (largest == 0.)
      return false; // a zero initial state has nothing to refine
    const unsigned int cells_before = mesh->n_global_active_cells();
    {
      TimerOutput::Scope m(computing_timer, "Mesh adaptation: marking");
      if (!convergence_study.refinement().flag_for_adaptation(
            *mesh,
            error_estimator.last_step_indicators(),
            displacement_problem.boundaries().contact_boundary_ids()))
        return false;
    }
    TimerOutput::Scope s(computing_timer, "Mesh adaptation: setup");
    mesh->execute_coarsening_and_refinement();
    setup_on_mesh();
    displacement_problem.assemble_stiffness_matrix();
    displacement_problem.initialize_linear_solver();
    compute_initial_state();
    pcout << "  initial mesh adapted: " << cells_before << " -> "
          << mesh->n_global_active_cells() << " cells, " << dof_handler.n_dofs()
          << " dofs" << std::endl;
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::change_mesh(const unsigned int n)
  {
    // What a checkpoint holds is what step n + 1 starts from: the same
    // vectors go to the new mesh, with the running maxima of the physics
    // objects and of the estimate, which their setup on the new mesh resets.
    std::optional<TimerOutput::Scope> part(std::in_place,
                                           computing_timer,
                                           "Mesh adaptation: transfer");
    CarriedState                      state;
    collect_carried_state(state);
    const auto         estimate_maxima = error_estimator.is_active() ?
                                           error_estimator.running_maxima() :
                                           std::map<std::string, double>();
    const unsigned int n_recorded
      = displacement_problem.predictor().n_recorded();

    // The fields of the step may still be written in the background from
    // the old mesh: that must end before the mesh changes.
    output_writer.finish_field_output(mpi_communicator);
    auto *const distributed
      = dynamic_cast<parallel::distributed::Triangulation<dim> *>(mesh.get());
    AssertThrow(distributed != nullptr, ExcInternalError());
    MeshTransfer<dim> transfer(*distributed,
                               dof_handler,
                               discretization.quadrature());
    transfer.prepare(state.vectors(displacement_problem.ghosted_solution()),
                     displacement_problem.history());
    mesh->execute_coarsening_and_refinement();

    part.emplace(computing_timer, "Mesh adaptation: setup");
    setup_on_mesh();
    part.emplace(computing_timer, "Mesh adaptation: transfer");
    receive_state(transfer, state.counters, n, n_recorded);
    part.emplace(computing_timer, "Mesh adaptation: setup");
    if (error_estimator.is_active())
      error_estimator.restore_running_maxima(estimate_maxima);
    displacement_problem.assemble_stiffness_matrix();
    displacement_problem.initialize_linear_solver();
  }



  template <int dim>
  void
  Simulator<dim>::receive_state(MeshTransfer<dim>                   &transfer,
                                const std::map<std::string, double> &counters,
                                const unsigned int                   n,
                                const unsigned int                   n_recorded)
  {
    // The vectors and the history on the new mesh. Values at hanging nodes
    // are set from the nodes they hang on, as the constraints of every
    // step demand (the interpolation gives them already where the old field
    // was linear along the edge; coarsening next to them may not).
    std::array<LA::MPI::Vector, 4> full;
    for (auto &v : full)
      v.reinit(locally_owned_dofs, mpi_communicator);
    LA::MPI::Vector sets_owned(locally_owned_dofs, mpi_communicator);
    transfer.unpack({&full[0], &full[1], &full[2], &full[3], &sets_owned},
                    displacement_problem.history());
    AffineConstraints<double> hanging(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    hanging.close();
    for (auto &v : full)
      hanging.distribute(v);
    displacement_problem.restore_fields(full);

    LA::MPI::Vector sets(locally_owned_dofs,
                         locally_relevant_dofs,
                         mpi_communicator);
    sets               = sets_owned;
    const auto counter = [&counters](const std::string &name) {
      const auto found = counters.find(name);
      AssertThrow(found != counters.end(), ExcInternalError());
      return found->second;
    };
    for (Physics<dim> *object : physics)
      stop_together(mpi_communicator, [&]() {
        object->read_transferred_state(sets_owned, sets, counter);
      });
    displacement_problem.resume_at(time_discretization.time(n), n_recorded);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
