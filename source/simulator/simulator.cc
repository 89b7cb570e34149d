// The simulator's parameters, construction, and time loop: the steps of the
// paper's scheme (14) in order.
#include <vpcontact/simulator/simulator.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>

namespace VPContact
{
  namespace
  {
    // The section "Damage", parsed before the element is built: whether
    // the scene has damage decides whether the FESystem has a damage
    // component. Its owner parses it, and the simulator asks the owner.
    template <int dim>
    const DamageModel<dim> &
    parsed_damage_model(DamageModel<dim> &model, ParameterHandler &prm)
    {
      model.parse_parameters(prm);
      return model;
    }

    // The section "Geometry", parsed first: its cell type chooses the
    // element and the triangulation.
    template <int dim>
    Geometry<dim>
    parsed_geometry(ParameterHandler  &prm,
                    const std::string &directory,
                    const MPI_Comm     communicator)
    {
      Geometry<dim> geometry;
      geometry.parse_parameters(prm, directory, communicator);
      return geometry;
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      std::to_string(dim),
                      Patterns::Integer(2, 3),
                      "Space dimension of the scene: 2 or 3.");
    Geometry<dim>::declare_parameters(prm);
    DisplacementProblem<dim>::declare_parameters(prm);
    DamageModel<dim>::declare_parameters(prm);
    InitialConditions::declare_parameters(prm);
    TimeDiscretization::declare_parameters(prm);
    DamageProblem<dim>::declare_parameters(prm);
    OutputWriter<dim>::declare_parameters(prm);
    Verification<dim>::declare_parameters(prm);
    MonitorPoints<dim>::declare_parameters(prm);
    ErrorEstimator<dim>::declare_parameters(prm);
    ConvergenceStudy<dim>::declare_parameters(prm);
    Checkpointing::declare_parameters(prm);
  }



  template <int dim>
  Simulator<dim>::Simulator(ParameterHandler  &prm,
                            const std::string &parameter_directory,
                            const MPI_Comm     communicator)
    : mpi_communicator(communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(communicator) == 0)
    // The timer is not tied to the communicator: its summary is rank 0's
    // view, and an input error thrown while the simulator is built does not
    // trigger TimerOutput's collective clean-up in its destructor.
    , computing_timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , geometry(parsed_geometry<dim>(prm, parameter_directory, communicator))
    , discretization(geometry.simplex_cells(),
                     parsed_damage_model(damage_model, prm).is_active())
    , mesh(discretization.make_triangulation(communicator))
    , dof_handler(*mesh)
    , displacement_problem(prm, access())
  {
    initial_conditions.parse_parameters(prm);
    time_discretization.parse_parameters(prm);
    output_writer.parse_parameters(prm);
    monitor_points.parse_parameters(prm);
    verification
      .parse_parameters(prm, discretization.finite_element().n_components());
    convergence_study.parse_parameters(prm,
                                       output_writer.directory(),
                                       time_discretization,
                                       geometry.base_level());
    geometry.set_finest_growth(convergence_study.refinement().largest_growth(
                                 geometry.global_refinements()),
                               convergence_study.refinement().size_entries());
    checkpointing.parse_parameters(prm, output_writer.base_directory());
    error_estimator
      .parse_parameters(prm, convergence_study.refinement().needs_indicators());
    if (damage_model.is_active())
      {
        damage_problem
          = std::make_unique<DamageProblem<dim>>(prm,
                                                 damage_model,
                                                 time_discretization,
                                                 displacement_problem.solver(),
                                                 output_writer.directory(),
                                                 computing_timer,
                                                 mpi_communicator);
        physics.push_back(damage_problem.get());
      }
    // The mesh file may change under the same name between a run and its
    // resumption.
    if (const std::string checksum = geometry.mesh_file_checksum();
        !checksum.empty())
      checkpointing.record_problem_input("Geometry/Mesh file (CRC-32)",
                                         checksum);
    // A checkpoint holds one run's state; the state of a sequence of cycles
    // (the table so far, the indicators of the current cycle) is not in it.
    AssertThrow(
      convergence_study.n_cycles() == 1
        || (!checkpointing.writes_periodically() && !checkpointing.resume()),
      ExcMessage("Checkpoint: runs with refinement cycles (Mesh "
                 "refinement/Number of cycles = "
                 + std::to_string(convergence_study.n_cycles())
                 + ") are not checkpointed in this release. Set "
                   "Checkpoint/Every steps = 0, Checkpoint/Every seconds = 0 "
                   "and Resume from checkpoint = false, or run the mesh of "
                   "one cycle as a single run."));
    displacement_problem.check_stability_limits();
    check_simplex_support();
    check_adaptation_schedule();
  }



  template <int dim>
  SimulatorAccess<dim>
  Simulator<dim>::access() const
  {
    return {mpi_communicator,
            pcout,
            computing_timer,
            discretization,
            *mesh,
            discretization.finite_element(),
            discretization.quadrature(),
            discretization.mapping(),
            dof_handler,
            locally_owned_dofs,
            locally_relevant_dofs,
            time_discretization,
            damage_model,
            output_writer};
  }



  template <int dim>
  const DisplacementProblem<dim> &
  Simulator<dim>::displacement() const
  {
    return displacement_problem;
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    // Everything that can be wrong with the input is checked before the
    // first solve: parameters (in the constructor), the output folder, the
    // mesh and its boundary ids, the reference compared with.
    output_writer.prepare_directory(mpi_communicator);
    if (!discretization.simplex())
      checkpointing.check_folders(output_writer.directory(), mpi_communicator);
    make_mesh();
    convergence_study.prepare(mpi_communicator);
    // Each cycle's timer table is that cycle's run and its mesh: the first
    // counts from the simulator's start, so that building (or reading) the
    // mesh is in its total as in the user's wall time, the later ones from
    // their refinement.
    for (unsigned int cycle = 0; cycle < convergence_study.n_cycles(); ++cycle)
      {
        if (cycle > 0)
          {
            computing_timer.reset();
            refine_mesh();
          }
        run_cycle(cycle);
        if (checkpointing.stopped())
          return;
      }
    pcout << convergence_study.table_text(
      output_writer.base_directory(),
      output_writer.deterministic_screen_output())
          << std::flush;
  }



  template <int dim>
  void
  Simulator<dim>::run_cycle(const unsigned int cycle)
  {
    // One run over [0, T] on the current mesh: set up the discrete problem,
    // then march in time.
    Timer              timer;
    const unsigned int first_step = setup_cycle(cycle);
    if (march(first_step))
      return;
    {
      TimerOutput::Scope t(computing_timer, "Postprocess and output");
      output_writer.finish_field_output(mpi_communicator);
    }
    print_summary(timer.wall_time());
    if (output_writer.report_solve_floor())
      displacement_problem.report_solve_floor();
    timer.stop();
    convergence_study.finish_cycle(*mesh,
                                   dof_handler.n_dofs(),
                                   time_discretization,
                                   error_estimator,
                                   timer.wall_time()
                                     - convergence_study.diagnostics_time(),
                                   output_writer.base_directory(),
                                   mpi_communicator);
  }



  template <int dim>
  unsigned int
  Simulator<dim>::setup_cycle(const unsigned int cycle)
  {
    // The mesh's degrees of freedom, quadrature data, damage problem and
    // matrix; returns the first step to compute.
    //
    // A new run's matrix depends only on the degrees of freedom and the
    // constraints with every contact node sticking, so it is assembled as
    // soon as they exist, and a Cholesky factorization of it then runs in
    // a second thread while this one sets up the rest (quadrature data,
    // damage problem, estimator) and computes the initial state and the
    // first step's right-hand side: the factorization does not gain from a
    // second BLAS thread, so the second core is otherwise idle. A resumed
    // run takes the state of its checkpoint's step, stick set included,
    // and continues after it (simulator_checkpoint.cc); its matrix comes
    // after that.
    start_cycle(cycle);
    if (!checkpointing.resume())
      {
        setup_on_mesh([this]() {
          displacement_problem.assemble_stiffness_matrix();
          displacement_problem.initialize_linear_solver(true);
        });
        print_header();
        return 1;
      }
    setup_on_mesh();
    const unsigned int first_step = restore_checkpoint() + 1;
    displacement_problem.assemble_stiffness_matrix();
    displacement_problem.initialize_linear_solver();
    print_header();
    return first_step;
  }



  template <int dim>
  bool
  Simulator<dim>::march(const unsigned int first_step)
  {
    // From here on SIGINT/SIGTERM/SIGUSR1 stop a single run at the end of a
    // step, with a checkpoint (runs with cycles are not checkpointed).
    // Returns whether the run stopped so.
    const auto signal_catcher
      = (checkpointing.stops_on_signal() && convergence_study.n_cycles() == 1
             && !discretization.simplex() ?
           std::make_unique<StopSignalCatcher>() :
           nullptr);
    try
      {
        if (!checkpointing.resume())
          {
            compute_initial_state();
            for (unsigned int i = 0;
                 i < convergence_study.refinement().initial_adaptations();
                 ++i)
              if (!adapt_initial_mesh())
                break;
            finish_step(0, 0.);
          }
        for (unsigned int n = first_step; n <= time_discretization.n_steps();
             ++n)
          {
            Timer step_timer;
            solve_step(n);
            step_timer.stop();
            finish_step(n, step_timer.wall_time());
            if (convergence_study.refinement()
                  .adapts_after_step(n, time_discretization.n_steps()))
              adapt_mesh(n);
            if (signal_catcher || checkpointing.writes_periodically())
              if (checkpoint_after_step(n))
                return true;
          }
      }
    catch (...)
      {
        // The fields written before the error stay readable: the piece
        // being written in the background is finished and recorded.
        output_writer.finish_field_output_after_error();
        throw;
      }
    return false;
  }



  template <int dim>
  void
  Simulator<dim>::finish_step(const unsigned int n, const double wall_time)
  {
    // The error estimate of step n (which also gives adaptive cycles their
    // indicators), then its statistics and output.
    postprocess_step(n, wall_time, estimate_error(n));
  }



  template <int dim>
  ErrorEstimate
  Simulator<dim>::estimate_error(const unsigned int n)
  {
    if (!error_estimator.estimates_step(n, time_discretization.n_steps()))
      return {std::numeric_limits<double>::quiet_NaN(),
              std::numeric_limits<double>::quiet_NaN()};
    TimerOutput::Scope t(computing_timer, "Error estimate");
    return error_estimator.estimate_step(
      n,
      time_discretization.step_size(),
      displacement_problem.kinematics().local_entries(
        displacement_problem.ghosted_solution()),
      displacement_problem.law(),
      displacement_problem.elastic_material().youngs_modulus());
  }



  template <int dim>
  bool
  Simulator<dim>::stopped_for_resume() const
  {
    return checkpointing.stopped();
  }



  template <int dim>
  void
  Simulator<dim>::compute_initial_state()
  {
    // u_0 = 0 and sigma_0 = 0 (set up by setup_dofs and setup_stress_history)
    // are the paper's data. Elastic equilibrium solves the elastic problem
    // with the load at t = 0, starting from that zero state, without the
    // viscoplastic rate: then sigma_0 = E eps(u_0).
    displacement_problem.reset_linear_iterations();
    if (initial_conditions.elastic_equilibrium())
      {
        displacement_problem.solve_increment(0., false);
        displacement_problem.update_stress(0);
      }
  }



  template <int dim>
  void
  Simulator<dim>::solve_step(const unsigned int n)
  {
    // Steps 1-3 of the scheme (predictor, displacement, stress) and step 4
    // (damage). The damage step uses only data of step n-1: the source
    // phi_{n-1} stored by the assembly of step 2, and zeta_{n-1}. zeta_n
    // enters the solution only after the stress update, which still reads
    // zeta_{n-1}.
    //
    // So the damage step need not wait for the displacement: with the
    // explicit scheme it runs beside the first displacement solve, as soon
    // as the first assembly has stored the source (begin_increment()). It
    // reads the damage entries of the solution, which the increment leaves
    // alone and which is only updated after the active-set loop, and the
    // source at the points, which the later active-set iterations reuse
    // as stored (assemble_rhs() with predictor_stored). The second thread
    // may meanwhile write the new stress at the points
    // (update_stress_ahead()), which the damage step does not read. The
    // implicit scheme's Newton iterations keep the order of the steps.
    std::vector<Physics<dim> *> stepping;
    std::copy_if(physics.begin(),
                 physics.end(),
                 std::back_inserter(stepping),
                 [](const Physics<dim> *object) {
                   return object->solves_in_step();
                 });
    const auto step = [this, n, &stepping]() {
      for (Physics<dim> *object : stepping)
        object->solve_step(n,
                           displacement_problem.solution_blocks(),
                           displacement_problem.history());
    };
    if (displacement_problem.implicit())
      {
        displacement_problem.solve_increment_implicit(
          time_discretization.time(n));
        step();
      }
    else
      {
        const double time = time_discretization.time(n);
        displacement_problem.begin_increment(time, true, !stepping.empty());
        // Should the work beside fail, the second thread is waited for
        // before the error is reported: it writes the increment and the
        // stress at the points.
        try
          {
            step();
          }
        catch (...)
          {
            displacement_problem.abandon_increment();
            throw;
          }
        displacement_problem.finish_increment(time, true);
      }
    displacement_problem.update_stress(n);
    for (Physics<dim> *object : stepping)
      object->store(n, displacement_problem.solution_blocks());
    if (!stepping.empty())
      displacement_problem.update_ghosted_solution();
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
