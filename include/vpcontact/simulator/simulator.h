// The simulator: owns the mesh, the degrees of freedom, the linear algebra
// and the physics modules, and calls them in the order of the paper's scheme.
#ifndef vpcontact_simulator_h
#define vpcontact_simulator_h

#include <vpcontact/checkpoint/checkpointing.h>
#include <vpcontact/contact/friction_problem.h>
#include <vpcontact/contact/tresca_friction.h>
#include <vpcontact/damage/damage_model.h>
#include <vpcontact/damage/damage_problem.h>
#include <vpcontact/fe/cell_kinematics.h>
#include <vpcontact/fe/conflict_free_chunks.h>
#include <vpcontact/fe/discretization.h>
#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/material/elastic_material.h>
#include <vpcontact/material/viscoplastic_law.h>
#include <vpcontact/postprocess/monitor_points.h>
#include <vpcontact/postprocess/output_writer.h>
#include <vpcontact/postprocess/statistics.h>
#include <vpcontact/postprocess/verification.h>
#include <vpcontact/problem_data/boundary_conditions.h>
#include <vpcontact/problem_data/geometry.h>
#include <vpcontact/problem_data/initial_conditions.h>
#include <vpcontact/refinement/convergence_study.h>
#include <vpcontact/refinement/error_estimator.h>
#include <vpcontact/refinement/mesh_transfer.h>
#include <vpcontact/simulator/displacement_problem.h>
#include <vpcontact/simulator/physics.h>
#include <vpcontact/simulator/simulator_access.h>
#include <vpcontact/simulator/time_discretization.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The quasistatic problem on a distributed mesh, in the manner of deal.II's
   * step-40 and step-42, discretised by the paper's scheme (14). The
   * simulator owns the mesh, its element and degrees of freedom (numbered
   * by blocks: displacement, then damage), the time loop in the paper's
   * order, the output folder and the checkpoint schedule; the physics live
   * in objects it builds and calls:
   * - DisplacementProblem: steps 1-3 (predictor, displacement increment
   *   with Tresca friction's active set, stress update);
   * - DamageProblem: step 4 (damage scenes only);
   * - ErrorEstimator, Verification, MonitorPoints, ConvergenceStudy: what
   *   a run reports of its accuracy, and the study around it.
   * Each gets a SimulatorAccess: references to what the simulator shares.
   *
   * The implementation is split by concern:
   * - simulator.cc: parameters, construction, the time loop, one step;
   * - simulator_cycles.cc: the start of a refinement cycle, the next mesh,
   *   the snapshot that ConvergenceStudy compares with a reference;
   * - simulator_setup.cc: mesh and degrees of freedom;
   * - simulator_adaptation.cc: the setup of everything on a mesh, and the
   *   adaptation of the mesh during a run with the state carried over;
   * - simulator_checks.cc: checks of the input across sections;
   * - simulator_output.cc: statistics, screen and field output;
   * - simulator_checkpoint.cc: writing a checkpoint, and resuming from one.
   */
  template <int dim>
  class Simulator
  {
  public:
    /// Declare every section the program reads (also for --print-parameters).
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read and check all parameters. @p parameter_directory is the folder
     * of the .prm file, against which relative input file names are taken.
     */
    Simulator(ParameterHandler  &prm,
              const std::string &parameter_directory,
              const MPI_Comm     communicator);

    /// Run the scene from t = 0 (or from a checkpoint) to T, once per
    /// refinement cycle.
    void
    run();

    /**
     * Whether run() stopped before T on a signal, after writing a
     * checkpoint (the program then exits with
     * exit_status_stopped_for_resume).
     */
    bool
    stopped_for_resume() const;

    /// What the physics objects share of the simulator: also for tools and
    /// tests that read the state a run ends in.
    SimulatorAccess<dim>
    access() const;

    /// Steps 1-3 and the contact (with its sets and multipliers as the
    /// last step left them).
    const DisplacementProblem<dim> &
    displacement() const;

  private:
    // simulator.cc
    void
    run_cycle(const unsigned int cycle);
    unsigned int
    setup_cycle(const unsigned int cycle);
    bool
    march(const unsigned int first_step);
    void
    finish_step(const unsigned int n, const double wall_time);
    ErrorEstimate
    estimate_error(const unsigned int n);
    void
    check_simplex_support() const;
    void
    check_adaptation_schedule() const;
    void
    compute_initial_state();
    void
    solve_step(const unsigned int n);

    // simulator_cycles.cc
    void
    start_cycle(const unsigned int cycle);
    void
    refine_mesh();
    Snapshot<dim>
    make_snapshot(const double time) const;

    // simulator_adaptation.cc
    /// The setup on the current mesh; @p after_dofs runs once the degrees
    /// of freedom and constraints exist, before the rest.
    void
    setup_on_mesh(const std::function<void()> &after_dofs = {});
    void
    adapt_mesh(const unsigned int n);
    void
    change_mesh(const unsigned int n);
    bool
    adapt_initial_mesh();
    void
    receive_state(MeshTransfer<dim>                   &transfer,
                  const std::map<std::string, double> &counters,
                  const unsigned int                   n,
                  const unsigned int                   n_recorded);

    // simulator_setup.cc
    void
    make_mesh();
    void
    setup_dofs();
    void
    number_dofs();

    // simulator_output.cc
    /// What the reports of a step (step_reports) read.
    struct StepReport
    {
      unsigned int                       n;
      double                             time;
      double                             u_max;
      const std::vector<Vector<double>> &components;
      StepQuantities                     quantities;
    };
    void
    check_finite(const StepMeasures &measures, const unsigned int n) const;
    double
    stress_error(const double time) const;
    void
    print_header() const;
    void
    postprocess_step(const unsigned int   n,
                     const double         step_wall_time,
                     const ErrorEstimate &estimate);
    std::string
    add_step_statistics(const unsigned int  n,
                        const double        step_wall_time,
                        const StepMeasures &measures);
    /// The list step_reports, once the physics objects are built.
    void
    collect_step_reports();
    void
    add_verification_statistics(std::string                       &line,
                                const double                       time,
                                const double                       u_max,
                                const std::vector<Vector<double>> &components);
    void
    write_fields(const unsigned int                 n,
                 const Vector<double>              &von_mises,
                 const std::vector<Vector<double>> &components);
    void
    print_summary(const double wall_time) const;

    // simulator_checkpoint.cc
    /**
     * The state step n + 1 starts from besides the solution and the stress
     * history: the last three increments, the physics objects' sets
     * (ghosted) and counters. A checkpoint writes it; an adaptation of the
     * mesh carries it to the new mesh.
     */
    struct CarriedState
    {
      std::map<std::string, double>  counters;
      LA::MPI::Vector                sets;
      std::array<LA::MPI::Vector, 3> increments;
      /// The vectors in the order of the files: @p solution (ghosted),
      /// the increments, the sets.
      std::vector<const LA::MPI::Vector *>
      vectors(const LA::MPI::Vector &solution) const
      {
        return {&solution,
                &increments[0],
                &increments[1],
                &increments[2],
                &sets};
      }
    };
    void
    collect_carried_state(CarriedState &state);
    void
    load_checkpoint_mesh();
    unsigned int
    restore_checkpoint();
    void
    read_checkpoint_fields(LA::MPI::Vector &sets_owned);
    void
    restore_output_records(const CheckpointMetadata &checkpoint);
    bool
    checkpoint_after_step(const unsigned int n);
    void
    write_checkpoint(const unsigned int n);
    /// Saves the fields of a checkpoint; returns the physics counters.
    std::map<std::string, double>
    write_checkpoint_fields(const std::string &folder);

    MPI_Comm            mpi_communicator;
    ConditionalOStream  pcout;
    mutable TimerOutput computing_timer;

    // The modules, each owning its section of the parameter file.
    Geometry<dim>         geometry;
    DamageModel<dim>      damage_model;
    InitialConditions     initial_conditions;
    TimeDiscretization    time_discretization;
    OutputWriter<dim>     output_writer;
    Verification<dim>     verification;
    MonitorPoints<dim>    monitor_points;
    ConvergenceStudy<dim> convergence_study;
    ErrorEstimator<dim>   error_estimator;
    Checkpointing         checkpointing;
    /// The checkpoint a resumed run reads (found by load_checkpoint_mesh()).
    CheckpointMetadata resumed_checkpoint;

    /// The element and rules of the mesh's cell type (Q1 or P1).
    const Discretization<dim> discretization;
    /// A p4est mesh of quadrilaterals (hexahedra), or a METIS-partitioned
    /// shared mesh of triangles (tetrahedra).
    const std::unique_ptr<parallel::TriangulationBase<dim>> mesh;
    DoFHandler<dim>                                         dof_handler;
    IndexSet                                                locally_owned_dofs;
    IndexSet locally_relevant_dofs;
    /// What makes the physics objects' output fields on locally_owned_dofs,
    /// and the ghost exchange from their layout to the solution's, both
    /// kept from one field output to the next: on several ranks a rank's
    /// degrees of freedom are two ranges (one per block), and a new layout
    /// of them would cost a table of its indices, a directory of their
    /// owners and a ghost import at every output (see OwnedLayout).
    OwnedLayout   output_layout;
    GhostExchange output_ghosts;
    /// Steps 1-3: the displacement, the stress and Tresca friction.
    DisplacementProblem<dim> displacement_problem;
    /// The damage problem, step 4 (damage scenes only).
    std::unique_ptr<DamageProblem<dim>> damage_problem;
    /// The physics objects this scene has (damage, friction): the
    /// simulator reports and checkpoints them through this list instead of
    /// testing for each.
    std::vector<Physics<dim> *> physics;
    /// What adds to a step's statistics row and screen line, in the order
    /// of the columns: the physics objects and the comparisons with exact
    /// and reference solutions (collect_step_reports()).
    std::vector<std::function<void(std::string &, const StepReport &)>>
      step_reports;

    Statistics statistics;
  };
} // namespace VPContact

#endif
