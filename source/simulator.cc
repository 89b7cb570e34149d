// The simulator's parameters, construction, and time loop.
#include <vpcontact/input_error.h>
#include <vpcontact/simulator.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>

#include <cmath>

namespace VPContact
{
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
    BoundaryConditions<dim>::declare_parameters(prm);
    TrescaFriction<dim>::declare_parameters(prm);
    TimeDiscretization::declare_parameters(prm);
    LinearSolver::declare_parameters(prm);
    OutputWriter<dim>::declare_parameters(prm);
    Verification<dim>::declare_parameters(prm);
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
    , triangulation(communicator,
                    typename Triangulation<dim>::MeshSmoothing(
                      Triangulation<dim>::smoothing_on_refinement
                      | Triangulation<dim>::smoothing_on_coarsening))
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
  {
    geometry.parse_parameters(prm, parameter_directory);
    material.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    friction.parse_parameters(prm);
    time_discretization.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    output_writer.parse_parameters(prm);
    verification.parse_parameters(prm);
  }



  template <int dim>
  void
  Simulator<dim>::run()
  {
    // Everything that can be wrong with the input is checked before the
    // first solve: parameters (in the constructor), the output folder, the
    // mesh and its boundary ids.
    output_writer.prepare_directory(mpi_communicator);
    make_mesh();
    setup_dofs();
    assemble_stiffness_matrix();
    {
      TimerOutput::Scope             t(computing_timer, "Build preconditioner");
      std::vector<std::vector<bool>> constant_modes;
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(dim, true),
                                       constant_modes);
      linear_solver.initialize(stiffness_matrix, constant_modes);
    }
    print_header();

    // The initial state u_0 = 0 of the paper.
    displacement_owned = 0.;
    displacement       = displacement_owned;
    postprocess_step(0, 0.);

    for (unsigned int n = 1; n <= time_discretization.n_steps(); ++n)
      {
        Timer step_timer;
        solve_step(n);
        step_timer.stop();
        postprocess_step(n, step_timer.wall_time());
      }
    print_summary();
  }



  template <int dim>
  void
  Simulator<dim>::solve_step(const unsigned int n)
  {
    assemble_load_vector(time_discretization.time(n));
    {
      TimerOutput::Scope t(computing_timer, "Solve");
      // The previous displacement is the start vector: in a slowly loaded
      // quasistatic run it is close to the new one.
      last_linear_iterations = linear_solver.solve(stiffness_matrix,
                                                   displacement_owned,
                                                   load_vector);
      constraints.distribute(displacement_owned);
    }
    AssertThrow(std::isfinite(displacement_owned.l2_norm()),
                ExcMessage("The displacement of step " + std::to_string(n)
                           + " (t = " + to_text(time_discretization.time(n))
                           + ") is not finite. The output up to the previous "
                             "step is complete in "
                           + output_writer.directory() + "."));
    displacement = displacement_owned;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
