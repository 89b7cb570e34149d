// The simulator's checkpoints: the state of a step written with the
// distributed mesh, and a run resumed from it (see doc/checkpoint.md).
#include <vpcontact/app/exit_agreement.h>
#include <vpcontact/checkpoint/checkpoint_fields.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/simulator/simulator.h>

#include <deal.II/distributed/tria.h>

#include <array>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace VPContact
{
  namespace
  {
    // The vectors in a checkpoint, in this order: u_n and zeta_n (the
    // solution), du_n, du_{n-1} and du_{n-2} (the increments from which
    // the start vector of the next solve is extrapolated, see
    // IncrementPredictor) and the active sets as an indicator vector
    // (FrictionActiveSet::write_state() and DamageBounds::write_state() use
    // different components).
    constexpr unsigned int n_checkpoint_vectors = 5;



    // The counter @p name of @p checkpoint, which a resumed run needs: a
    // checkpoint.json without it cannot be resumed from, so its absence
    // ends the run with a message rather than starting from a wrong state.
    double
    checkpoint_counter(const CheckpointMetadata &checkpoint,
                       const std::string        &name)
    {
      const auto found = checkpoint.counters.find(name);
      AssertThrow(found != checkpoint.counters.end(),
                  ExcMessage("The checkpoint in " + checkpoint.folder
                             + " has no counter " + name
                             + " in its checkpoint.json."));
      return found->second;
    }

    // The p4est mesh that checkpoints save and load. Simplex meshes are not
    // checkpointed (Simulator::check_simplex_support() says so first).
    template <int dim>
    parallel::distributed::Triangulation<dim> &
    checkpointed_mesh(parallel::TriangulationBase<dim> &triangulation)
    {
      auto *const mesh
        = dynamic_cast<parallel::distributed::Triangulation<dim> *>(
          &triangulation);
      AssertThrow(mesh != nullptr,
                  ExcMessage("Checkpoints need a mesh of quadrilaterals "
                             "(hexahedra)."));
      return *mesh;
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::write_checkpoint(const unsigned int n)
  {
    TimerOutput::Scope t(computing_timer, "Checkpoint");
    // What deal.II writes for every cell: the cell's values of each vector
    // and the stress history of its quadrature points (doubles), and the
    // cell's refinement status. The file of these fixed-size records is by
    // far the largest of a checkpoint; the p4est forest takes less than 64
    // bytes a cell, the small files less than 64 kB.
    const std::size_t bytes_per_cell
      = sizeof(double)
          * (n_checkpoint_vectors
               * discretization.finite_element().n_dofs_per_cell()
             + discretization.quadrature().size()
                 * QuadraturePointHistory<dim>::n_values)
        + sizeof(unsigned int);
    const double      n_cells = mesh->n_global_active_cells();
    const std::string folder
      = checkpointing.start_writing(n_cells * (bytes_per_cell + 64) + 65536,
                                    mpi_communicator);

    const std::map<std::string, double> physics_counters
      = write_checkpoint_fields(folder);

    CheckpointMetadata metadata;
    metadata.step = n;
    metadata.time = time_discretization.time(n);
    // The refinement cycle goes here once the time loop has cycles; a
    // resumed run would then also start its loop at this cycle.
    metadata.cycle          = 0;
    metadata.n_ranks        = Utilities::MPI::n_mpi_processes(mpi_communicator);
    metadata.n_coarse_cells = mesh->n_global_coarse_cells();
    metadata.n_active_cells = mesh->n_global_active_cells();
    metadata.n_dofs         = dof_handler.n_dofs();
    metadata.statistics_csv = statistics.to_csv();
    // The checkpoint lists the field outputs on disk: the last one must be.
    output_writer.finish_field_output(mpi_communicator);
    metadata.field_outputs = output_writer.field_outputs();
    // Where they are: a run resumed into another folder brings them.
    metadata.output_directory
      = std::filesystem::absolute(output_writer.directory())
          .lexically_normal()
          .string();
    metadata.counters = verification.running_maxima();
    metadata.counters.insert(physics_counters.begin(), physics_counters.end());
    if (error_estimator.is_active())
      {
        const auto maxima = error_estimator.running_maxima();
        metadata.counters.insert(maxima.begin(), maxima.end());
      }
    metadata.parameters = checkpointing.problem_parameters();
    checkpointing.finish_writing(
      metadata,
      CheckpointFields::expected_sizes(checkpointed_mesh(*mesh),
                                       "mesh",
                                       bytes_per_cell),
      mpi_communicator);
    pcout << "  checkpoint of step " << n << " written to "
          << checkpointing.folder() << std::endl;
  }



  // The fields of a checkpoint, into @p folder/mesh with the distributed
  // mesh: the vectors listed at n_checkpoint_vectors, in that order, and the
  // stress history. Returns the counters of the friction and damage
  // problems and the displacement problem's (the predictor's and the
  // solver choice's), which checkpoint.json holds with the other counters.
  template <int dim>
  std::map<std::string, double>
  Simulator<dim>::write_checkpoint_fields(const std::string &folder)
  {
    // The state that step n + 1 starts from. The stress predictor and the
    // damage source at the quadrature points are recomputed by the next
    // assembly, but are stored with the stress: the resumed state is then
    // the same bits as the uninterrupted one.
    CarriedState state;
    collect_carried_state(state);
    const std::vector<const LA::MPI::Vector *> vectors
      = state.vectors(displacement_problem.ghosted_solution());
    AssertDimension(vectors.size(), n_checkpoint_vectors);
    CheckpointFields::save(checkpointed_mesh(*mesh),
                           dof_handler,
                           vectors,
                           displacement_problem.history(),
                           discretization.quadrature().size(),
                           folder + "/mesh");
    state.counters.merge(displacement_problem.checkpoint_counters());
    return state.counters;
  }



  template <int dim>
  void
  Simulator<dim>::collect_carried_state(CarriedState &state)
  {
    // Scenes without friction or damage keep their counters at 0.
    state.counters = {{"max_friction_violation", 0.},
                      {"max_damage_violation", 0.},
                      {"damage_rings_ahead", 0.}};
    LA::MPI::Vector sets_owned(locally_owned_dofs, mpi_communicator);
    for (const Physics<dim> *object : physics)
      object->write_checkpoint(sets_owned, state.counters);
    state.sets.reinit(locally_owned_dofs,
                      locally_relevant_dofs,
                      mpi_communicator);
    state.sets       = sets_owned;
    state.increments = displacement_problem.increments_for_checkpoint();
  }



  template <int dim>
  bool
  Simulator<dim>::checkpoint_after_step(const unsigned int n)
  {
    const auto decision = checkpointing.decide(n,
                                               time_discretization.n_steps(),
                                               mpi_communicator);
    if (decision.write)
      write_checkpoint(n);
    if (!decision.stop)
      return false;

    checkpointing.note_stopped_on_signal();
    std::ostringstream message;
    message << "\nStopped on " << StopSignalCatcher::name(decision.signal)
            << " at the end of step " << n << " of "
            << time_discretization.n_steps()
            << " (t = " << time_discretization.time(n)
            << "); the checkpoint in " << checkpointing.folder()
            << " holds this state.\nTo continue the run, start it again with "
               "--resume (vpcontact --resume SCENE.prm) or with "
               "Checkpoint/Resume from checkpoint = true. Exit status "
            << exit_status_stopped_for_resume << '.' << std::endl;
    // With the reader of the screen output gone (a pipe into head), the
    // error output is where this can still be read.
    if (StopSignalCatcher::output_pipe_broken())
      {
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          std::cerr << "\nThe screen output (a pipe) lost its reader."
                    << message.str() << std::flush;
      }
    else
      pcout << message.str() << std::flush;
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::load_checkpoint_mesh()
  {
    // The newest complete checkpoint, checked file by file before p4est
    // reads it, and checked to be of this problem.
    resumed_checkpoint = checkpointing.find_checkpoint(mpi_communicator, pcout);
    checkpointing.check_compatibility(resumed_checkpoint);
    const std::string folder = resumed_checkpoint.folder;
    VPContactCheckParameter(
      resumed_checkpoint.step < time_discretization.n_steps(),
      "Time/End time",
      time_discretization.end_time(),
      "the checkpoint in " + folder + " is at step "
        + std::to_string(resumed_checkpoint.step)
        + " (t = " + to_text(resumed_checkpoint.time) + "), and this run has "
        + std::to_string(time_discretization.n_steps())
        + " steps: nothing is left to do. Raise the end time to continue the "
          "run.");

    // load() refines the coarse mesh as the checkpoint's was, and
    // partitions it among the ranks of this run.
    geometry.create_coarse_mesh(*mesh);
    AssertThrow(mesh->n_global_coarse_cells()
                  == resumed_checkpoint.n_coarse_cells,
                ExcMessage("The checkpoint in " + folder + " has "
                           + std::to_string(resumed_checkpoint.n_coarse_cells)
                           + " coarse cells, the mesh of the Geometry section "
                             "has "
                           + std::to_string(mesh->n_global_coarse_cells())
                           + ": has the mesh file changed? Resume with the "
                             "mesh of the checkpointed run."));
    checkpointed_mesh(*mesh).load(folder + "/mesh");
    AssertThrow(mesh->n_global_active_cells()
                  == resumed_checkpoint.n_active_cells,
                ExcMessage("The mesh loaded from " + folder
                           + " does not have the number of cells the "
                             "checkpoint records."));
  }



  template <int dim>
  unsigned int
  Simulator<dim>::restore_checkpoint()
  {
    TimerOutput::Scope t(computing_timer, "Checkpoint");
    const auto        &checkpoint = resumed_checkpoint;
    const std::string &folder     = checkpoint.folder;
    AssertThrow(dof_handler.n_dofs() == checkpoint.n_dofs,
                ExcMessage("The checkpoint in " + folder + " has "
                           + std::to_string(checkpoint.n_dofs)
                           + " degrees of freedom, this run "
                           + std::to_string(dof_handler.n_dofs()) + "."));

    LA::MPI::Vector sets_owned(locally_owned_dofs, mpi_communicator);
    read_checkpoint_fields(sets_owned);

    // The active sets, and the constraints as the uninterrupted run has
    // them after step n: the stick nodes of the restored set (they shape the
    // matrix, which run() assembles next), and prescribed displacements with
    // the increment g(t_n) - u_n, zero at the end of a step. The explicit
    // step rebuilds them for its own time anyway; the implicit step starts
    // its first Newton correction from them.
    LA::MPI::Vector sets(locally_owned_dofs,
                         locally_relevant_dofs,
                         mpi_communicator);
    sets               = sets_owned;
    const auto counter = [&](const std::string &name) {
      return checkpoint_counter(checkpoint, name);
    };
    // A state that does not fit the nodes is found by the ranks that own
    // them: all ranks stop together (each read calls collective functions,
    // so each is a step of its own).
    for (Physics<dim> *object : physics)
      stop_together(mpi_communicator, [&]() {
        object->read_checkpoint(sets_owned, sets, counter);
      });
    displacement_problem.resume_at(time_discretization.time(checkpoint.step),
                                   static_cast<unsigned int>(
                                     counter("recorded_increments")));
    displacement_problem.restore_solver_choice(checkpoint.counters);
    restore_output_records(checkpoint);

    pcout << "Resuming from the checkpoint in " << folder << ": step "
          << checkpoint.step << ", t = " << checkpoint.time;
    if (!output_writer.deterministic_screen_output())
      pcout << " (written on " << checkpoint.n_ranks << " MPI rank(s))";
    pcout << '\n' << std::endl;
    return checkpoint.step;
  }



  // The fields of the checkpoint, in the order write_checkpoint_fields()
  // saved them, and the stress history. The vectors come back without
  // ghosts; the ghosted copies are made from them. The active sets go into
  // @p sets_owned, which the friction and damage problems read.
  template <int dim>
  void
  Simulator<dim>::read_checkpoint_fields(LA::MPI::Vector &sets_owned)
  {
    // The files hold vectors on all degrees of freedom (see
    // DisplacementProblem::restore_fields()).
    std::array<LA::MPI::Vector, 4> full;
    for (auto &v : full)
      v.reinit(locally_owned_dofs, mpi_communicator);
    const std::vector<LA::MPI::Vector *> vectors
      = {&full[0], &full[1], &full[2], &full[3], &sets_owned};
    AssertDimension(vectors.size(), n_checkpoint_vectors);
    CheckpointFields::load(checkpointed_mesh(*mesh),
                           dof_handler,
                           vectors,
                           displacement_problem.history(),
                           discretization.quadrature().size());
    displacement_problem.restore_fields(full);
  }



  // What the run has written so far, as it stood at @p checkpoint: the
  // table and the .pvd record continue from there, whatever the stopped
  // run wrote after it, and so do the running maxima of the verification.
  template <int dim>
  void
  Simulator<dim>::restore_output_records(const CheckpointMetadata &checkpoint)
  {
    statistics.read_csv(checkpoint.statistics_csv);
    output_writer.write_statistics(statistics, mpi_communicator);
    pcout << output_writer.restore_field_outputs(checkpoint.field_outputs,
                                                 checkpoint.output_directory,
                                                 mpi_communicator);
    verification.restore_running_maxima(checkpoint.counters);
    if (error_estimator.is_active())
      error_estimator.restore_running_maxima(checkpoint.counters);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
