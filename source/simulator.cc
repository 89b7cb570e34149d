// The simulator's parameters, construction, and time loop: the steps of the
// paper's scheme (14) in order.
#include <vpcontact/finite_values.h>
#include <vpcontact/input_error.h>
#include <vpcontact/simulator.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>

#include <cmath>

namespace VPContact
{
  namespace
  {
    // Whether the scene has damage: read here because the element is built
    // before the modules parse their sections.
    bool
    with_damage(ParameterHandler &prm)
    {
      prm.enter_subsection("Damage");
      const bool damage = (prm.get("Model") != "none");
      prm.leave_subsection();
      return damage;
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
    ElasticMaterial<dim>::declare_parameters(prm);
    ViscoplasticityParameters<dim>::declare_parameters(prm);
    DamageModel<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    TrescaFriction<dim>::declare_parameters(prm);
    InitialConditions::declare_parameters(prm);
    TimeDiscretization::declare_parameters(prm);
    LinearSolver::declare_parameters(prm);
    DamageProblem<dim>::declare_parameters(prm);
    IncrementPredictor::declare_parameters(prm);
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
    , discretization(geometry.simplex_cells(), with_damage(prm))
    , mesh(discretization.make_triangulation(communicator))
    , triangulation(*mesh)
    , fe(discretization.finite_element())
    , quadrature(discretization.quadrature())
    , mapping(discretization.mapping())
    , dof_handler(triangulation)
  {
    material.parse_parameters(prm);
    viscoplasticity.parse_parameters(prm);
    viscoplastic_law = viscoplasticity.create_law(prm);
    damage_model.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    friction.parse_parameters(prm);
    initial_conditions.parse_parameters(prm);
    time_discretization.parse_parameters(prm);
    displacement.solver.parse_parameters(prm);
    increment_predictor.parse_parameters(prm);
    output_writer.parse_parameters(prm);
    monitor_points.parse_parameters(prm);
    verification.parse_parameters(prm, fe.n_components());
    convergence_study.parse_parameters(prm,
                                       output_writer.directory(),
                                       time_discretization);
    geometry.set_finest_growth(convergence_study.refinement().largest_growth(
                                 geometry.global_refinements()),
                               convergence_study.refinement().size_entries());
    checkpointing.parse_parameters(prm);
    error_estimator
      .parse_parameters(prm, convergence_study.refinement().needs_indicators());
    if (damage_model.is_active())
      damage_problem
        = std::make_unique<DamageProblem<dim>>(prm,
                                               damage_model,
                                               time_discretization,
                                               displacement.solver,
                                               output_writer.directory(),
                                               computing_timer,
                                               mpi_communicator);
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
    check_stability_limits();
    check_simplex_support();
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first < dim)
        displacement.shape_functions.push_back(i);
  }



  template <int dim>
  Simulator<dim>::~Simulator()
  {
    // Members are destroyed in reverse order of declaration, the matrices
    // before the linear solver; a factorization (MUMPS) must go first.
    displacement.solver.clear();
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
    for (unsigned int cycle = 0; cycle < convergence_study.n_cycles(); ++cycle)
      {
        if (cycle > 0)
          refine_mesh();
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
    output_writer.finish_field_output(mpi_communicator);
    print_summary(timer.wall_time());
    if (output_writer.report_solve_floor())
      report_solve_floor();
    timer.stop();
    convergence_study.finish_cycle(triangulation,
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
    start_cycle(cycle);
    setup_dofs();
    setup_stress_history();
    if (damage_problem)
      {
        damage_problem->setup(dof_handler,
                              quadrature,
                              locally_owned_dofs,
                              locally_relevant_dofs,
                              solution_owned);
        solution = solution_owned;
      }
    // A resumed run takes the state of its checkpoint's step and continues
    // after it (simulator_checkpoint.cc).
    const unsigned int first_step
      = (checkpointing.resume() ? restore_checkpoint() + 1 : 1);
    assemble_stiffness_matrix();
    initialize_linear_solver();
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
            finish_step(0, 0.);
          }
        for (unsigned int n = first_step; n <= time_discretization.n_steps();
             ++n)
          {
            Timer step_timer;
            solve_step(n);
            step_timer.stop();
            finish_step(n, step_timer.wall_time());
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
    if (!error_estimator.is_active())
      return {std::numeric_limits<double>::quiet_NaN(),
              std::numeric_limits<double>::quiet_NaN()};
    TimerOutput::Scope t(computing_timer, "Error estimate");
    return error_estimator.estimate_step(n,
                                         time_discretization.step_size(),
                                         cell_kinematics.local_entries(
                                           solution),
                                         *viscoplastic_law,
                                         material.youngs_modulus());
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
    last_linear_iterations = 0;
    if (initial_conditions.elastic_equilibrium())
      {
        solve_increment(0., false);
        update_stress(0);
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
    if (viscoplasticity.implicit())
      solve_increment_implicit(time_discretization.time(n));
    else
      solve_increment(time_discretization.time(n), true);
    if (damage_problem)
      damage_problem->solve(n, solution_owned, stress_history);
    update_stress(n);
    if (damage_problem)
      {
        damage_problem->store(n, solution_owned);
        solution = solution_owned;
      }
  }



  template <int dim>
  void
  Simulator<dim>::initialize_linear_solver()
  {
    TimerOutput::Scope t(computing_timer, "Build preconditioner");
    // A matrix with an infinite entry makes the factorizations fail deep
    // inside the libraries (ML writes a dump file of it): refuse it here.
    AssertThrow(std::isfinite(displacement.matrix.frobenius_norm()),
                ExcMessage("The stiffness matrix is not finite: Material/"
                           "Young's modulus = "
                           + to_text(material.youngs_modulus())
                           + " overflows with the cell sizes of this mesh. "
                             "Rescale the units of the scene."));
    displacement.solver.initialize(displacement.matrix, rigid_motions());
  }



  template <int dim>
  void
  Simulator<dim>::solve_increment(const double time,
                                  const bool   with_viscoplastic_rate)
  {
    if (friction_problem)
      friction_problem->begin_step(time);
    if (boundary_conditions.has_prescribed_displacement())
      make_constraints(time, &solution);

    // Without friction one linear solve. With friction, the primal-dual
    // active set iteration: solve with the current stick and slip sets,
    // recompute the friction multipliers from the residual, take the next
    // sets; stop when no node changes. The sets of the previous step are
    // the start (warm start).
    last_linear_iterations = 0;
    // The first start vector: the increments of the last steps
    // extrapolated (see IncrementPredictor); the active-set iterations of
    // a step then start from the previous iterate.
    if (with_viscoplastic_rate)
      increment_predictor.predict(increment_owned);
    for (unsigned int iteration = 1;; ++iteration)
      {
        assemble_rhs(time, with_viscoplastic_rate);
        if (friction_problem)
          friction_problem->add_slip_forces(constraints, displacement.rhs);
        solve_displacement();
        if (!friction_problem || friction_sets_settled(time, iteration))
          break;
      }

    AssertThrow(all_finite(increment_owned, mpi_communicator),
                ExcMessage("The displacement increment at t = " + to_text(time)
                           + " is not finite. The output up to the previous "
                             "step is complete in "
                           + output_writer.directory() + "."));
    if (with_viscoplastic_rate)
      increment_predictor.record(increment_owned);
    solution_owned += increment_owned;
    solution = solution_owned;
  }



  template <int dim>
  void
  Simulator<dim>::solve_displacement()
  {
    if (displacement.solver.preconditioner_outdated())
      initialize_linear_solver();
    TimerOutput::Scope t(computing_timer, "Solve");
    // K du = b on the displacement block, whose entries lead the local
    // entries of the full vector (see setup_dofs()), from the current
    // increment.
    std::copy_n(increment_owned.begin(),
                displacement.increment.locally_owned_size(),
                displacement.increment.begin());
    last_linear_iterations
      += displacement.solver.solve(displacement.increment, displacement.rhs);
    std::copy(displacement.increment.begin(),
              displacement.increment.end(),
              increment_owned.begin());
    constraints.distribute(increment_owned);
    increment = increment_owned;
  }



  template <int dim>
  bool
  Simulator<dim>::friction_sets_settled(const double       time,
                                        const unsigned int iteration)
  {
    // The next stick and slip sets from the multipliers of this solve.
    // The matrix changes when a node enters or leaves the stick set (its
    // constraints change) or, in 3D, when a slip direction turns (its slip
    // stiffness changes); then it is reassembled.
    const auto changes
      = friction_problem->update(increment,
                                 material.youngs_modulus(),
                                 [this](const auto &cells, auto &residual) {
                                   assemble_residual(cells, residual);
                                 });
    if (changes.n_stick_changed > 0)
      check_held_while_slipping(time);
    if (changes.n_changed == 0)
      return true;
    AssertThrow(
      iteration < friction.max_iterations(),
      ExcMessage(
        "The stick/slip active set did not converge at t = " + to_text(time)
        + ": after " + std::to_string(iteration) + " iterations "
        + std::to_string(changes.n_changed)
        + " contact node(s) still change set or slip direction. Raise Contact/Maximum active "
          "set iterations = "
        + std::to_string(friction.max_iterations())
        + ", try another Contact/Complementarity factor, or (3D) raise "
          "Contact/Slip direction tolerance = "
        + to_text(friction.direction_tolerance())
        + " if a displacement solver's tolerance keeps the directions "
          "from settling. The output up "
          "to the previous step is complete in "
        + output_writer.directory() + "."));
    if (changes.n_stick_changed > 0)
      {
        make_constraints(time, &solution);
        assemble_stiffness_matrix();
        initialize_linear_solver();
      }
    else if (changes.n_matrix_changed > 0)
      {
        // Only slip directions turned: the matrix changes at those nodes,
        // and the preconditioner or factors of the matrix as it was still
        // precondition CG well (LinearSolver::matrix_changed()).
        friction_problem->update_slip_stiffness(constraints,
                                                displacement.matrix);
        displacement.solver.matrix_changed();
      }
    return false;
  }



  template <int dim>
  void
  Simulator<dim>::report_solve_floor()
  {
    // The floor of a time step: one solve of the displacement system with
    // everything reused (matrix and preconditioner as they are, the last
    // right-hand side), from a zero start vector.
    TrilinosWrappers::MPI::Vector x(displacement.increment);
    x = 0.;
    Timer              timer;
    const unsigned int iterations
      = displacement.solver.solve(x, displacement.rhs);
    timer.stop();

    // Its two kernels, each timed over ten applications: they tell how the
    // solve scales with the ranks (scripts/bench compares them).
    TrilinosWrappers::MPI::Vector y(x);
    Timer                         matvec_timer;
    for (unsigned int i = 0; i < 10; ++i)
      displacement.matrix.vmult(y, x);
    matvec_timer.stop();
    Timer preconditioner_timer;
    for (unsigned int i = 0; i < 10; ++i)
      displacement.solver.precondition(y, displacement.rhs);
    preconditioner_timer.stop();
    const bool        cg = !displacement.solver.is_direct();
    const std::string how
      = (cg ? std::to_string(iterations) + " CG iterations" :
              std::string("solve with the factors"));
    pcout << "Solve floor: one displacement solve takes " << timer.wall_time()
          << " s (" << how << ", " << displacement.matrix.m()
          << " dofs); one matrix-vector product "
          << 100. * matvec_timer.wall_time() << " ms, "
          << (cg ? "one preconditioner application " :
                   "one solve with the factors ")
          << 100. * preconditioner_timer.wall_time() << " ms" << std::endl;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
