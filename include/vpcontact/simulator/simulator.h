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
#include <vpcontact/simulator/displacement_system.h>
#include <vpcontact/simulator/increment_predictor.h>
#include <vpcontact/simulator/physics.h>
#include <vpcontact/simulator/time_discretization.h>
#include <vpcontact/simulator/work_ahead.h>

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
#include <string>
#include <thread>

namespace VPContact
{
  using namespace dealii;

  /**
   * The quasistatic problem on a distributed mesh, in the manner of deal.II's
   * step-40 and step-42, discretised by the paper's scheme (14).
   *
   * The implementation is split by concern:
   * - simulator.cc: parameters, construction, the time loop, one step;
   * - simulator_solve.cc: the displacement increment of a step (the
   *   stick/slip active set around the linear solves, the first solve
   *   beside the damage step), the solve floor;
   * - simulator_cycles.cc: the start of a refinement cycle, the next mesh,
   *   the snapshot that ConvergenceStudy compares with a reference;
   * - simulator_setup.cc: mesh, degrees of freedom, constraints, sparsity,
   *   quadrature point storage;
   * - simulator_assembly.cc: the stiffness matrix (once per mesh) and the
   *   right-hand side of a step;
   * - simulator_implicit.cc: the backward Euler alternative to step 1-3;
   * - simulator_stress.cc: the stress update and its safeguards;
   * - simulator_output.cc: statistics, screen and field output;
   * - simulator_checkpoint.cc: writing a checkpoint, and resuming from one.
   *
   * The optional physics and the study around a run live in classes of
   * their own, which the simulator builds and calls: DamageProblem (step 4,
   * damage scenes only), FrictionProblem (Tresca friction, g > 0 only),
   * ConvergenceStudy (refinement cycles, errors against a reference). The
   * displacement problem's linear system is a DisplacementSystem.
   *
   * The unknowns are the displacement, Q1 in every component of one
   * FESystem (P1 on triangles and tetrahedra, see Discretization), and the
   * stress at the quadrature points of the assembly rule. A step solves for
   * the increment du = u_n - u_{n-1} = k w (the paper's velocity problem
   * multiplied by k, so the matrix is E and does not depend on k):
   *
   *   (E eps(du), eps(v)) = (f_n, v) - (sigma_{n-1} + k G_{n-1}, eps(v)),
   *
   * then sets sigma_n = sigma_{n-1} + k G_{n-1} + E eps(du).
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

    /// Releases the linear solver before the matrix it refers to.
    ~Simulator();

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

  private:
    /**
     * The FEValues of a pass over the cells that assembles forces: values,
     * gradients, points and weights on the cell, and on faces for the
     * traction (the rule of the stress history and a Gauss rule on faces).
     * One per thread of a pass over the cells.
     */
    struct AssemblyScratch
    {
      AssemblyScratch(const Mapping<dim>        &mapping,
                      const FiniteElement<dim>  &fe,
                      const Quadrature<dim>     &quadrature,
                      const Quadrature<dim - 1> &face_quadrature)
        : fe_values(mapping,
                    fe,
                    quadrature,
                    update_values | update_gradients | update_quadrature_points
                      | update_JxW_values)
        , fe_face_values(mapping,
                         fe,
                         face_quadrature,
                         update_values | update_quadrature_points
                           | update_JxW_values)
        , strains(quadrature.size())
        , weighted_predictor(quadrature.size())
        , damage_values(quadrature.size(), 1.)
      {}
      AssemblyScratch(const AssemblyScratch &scratch)
        : AssemblyScratch(scratch.fe_values.get_mapping(),
                          scratch.fe_values.get_fe(),
                          scratch.fe_values.get_quadrature(),
                          scratch.fe_face_values.get_quadrature())
      {}
      FEValues<dim>                        fe_values;
      FEFaceValues<dim>                    fe_face_values;
      std::vector<SymmetricTensor<2, dim>> strains;
      std::vector<SymmetricTensor<2, dim>> weighted_predictor;
      std::vector<double>                  damage_values;
      /// On all shape functions of the cell, the damage ones included.
      Vector<double> cell_vector;
      /// The damage source of the thread that last used this scratch
      /// (DamageModel::source() looks it up in a thread-local storage, a
      /// lock each time): fetched again only when the thread changes.
      const DamageSource<dim> *damage_source = nullptr;
      std::thread::id          damage_source_thread;
    };

    /// What a cell adds to the right-hand side: its vector and, where a
    /// constraint is inhomogeneous, its matrix (see assemble_rhs()). A
    /// plain cell has only locally owned, unconstrained degrees of freedom:
    /// its entries are added to the vector's local storage directly.
    struct CellRhs
    {
      explicit CellRhs(const unsigned int dofs_per_cell)
        : cell_rhs(dofs_per_cell)
        , cell_matrix(dofs_per_cell, dofs_per_cell)
        , dof_indices(dofs_per_cell)
      {}
      Vector<double>                       cell_rhs;
      FullMatrix<double>                   cell_matrix;
      std::vector<types::global_dof_index> dof_indices;
      bool                                 inhomogeneous = false;
      bool                                 plain         = false;
    };

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
    check_stability_limits() const;
    void
    check_simplex_support() const;
    /// Stop with a message if no contact node sticks and the other
    /// constraints leave the body a rigid motion (simulator_checks.cc).
    void
    check_held_while_slipping(const double time) const;
    void
    compute_initial_state();
    void
    solve_step(const unsigned int n);

    // simulator_solve.cc
    /**
     * The displacement increment of the step at @p time. @p beside, if
     * given, runs once, in the first active-set iteration after its
     * right-hand side is assembled: while that solve's substitutions run
     * in a second thread where the linear solver allows it
     * (LinearSolver::solves_in_background()), else just before the solve.
     * It must not touch the displacement system's vectors or solver, and
     * must read nothing that the later iterations change.
     */
    void
    solve_increment(const double                 time,
                    const bool                   with_viscoplastic_rate,
                    const std::function<void()> &beside = {});
    void
    solve_displacement();
    void
    solve_displacement_beside(const std::function<void()> &beside);
    /// After a solve: the constrained entries of du, and its ghosted copy.
    void
    share_increment();
    bool
    friction_sets_settled(const double time, const unsigned int iteration);
    void
    initialize_linear_solver();
    void
    report_solve_floor();

    // simulator_cycles.cc
    void
    start_cycle(const unsigned int cycle);
    void
    refine_mesh();
    Snapshot<dim>
    make_snapshot(const double time) const;

    // simulator_setup.cc
    void
    make_mesh();
    void
    setup_dofs();
    void
    number_dofs();
    void
    setup_vectors();
    void
    setup_displacement_matrix();
    void
    make_constraints(const double time, const LA::MPI::Vector *previous);
    void
    add_displacement_hanging_nodes();
    void
    setup_stress_history();
    NearNullSpace
    rigid_motions() const;
    /// The displacement degrees of freedom of @p cell, in the order of
    /// displacement.shape_functions.
    void
    get_displacement_dof_indices(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      std::vector<types::global_dof_index>                 &indices) const;

    // simulator_assembly.cc
    void
    assemble_stiffness_matrix();
    /// The right-hand side at @p time. With @p predictor_stored the
    /// predictor and the damage source at the points are those a pass of
    /// the same step stored (the later active-set iterations), and only
    /// their work and the loads are assembled.
    void
    assemble_rhs(const double time,
                 const bool   with_viscoplastic_rate,
                 const bool   predictor_stored = false);
    void
    assemble_residual(
      const std::vector<typename DoFHandler<dim>::active_cell_iterator> &cells,
      LA::MPI::Vector &residual) const;
    void
    add_cell_loads(const typename DoFHandler<dim>::active_cell_iterator &cell,
                   const FEValues<dim> &fe_values,
                   FEFaceValues<dim>   &fe_face_values,
                   Vector<double>      &cell_vector) const;
    void
    compute_cell_rhs(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     const double        previous_time,
                     const bool          evaluate_rate,
                     const bool          predictor_stored,
                     const double *const solution_entries,
                     AssemblyScratch    &scratch);
    void
    add_other_cells(const double        previous_time,
                    const bool          evaluate_rate,
                    const bool          predictor_stored,
                    const bool          body_force,
                    const double *const solution_entries);
    void
    subtract_predictor_work(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      AssemblyScratch                                      &scratch) const;
    void
    add_plain_cells(const unsigned int  color,
                    const double        previous_time,
                    const bool          evaluate_rate,
                    const bool          predictor_stored,
                    const bool          body_force,
                    const double *const solution_entries);
    void
    add_cell_loads_and_lifts(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const bool                                            body_force,
      AssemblyScratch                                      &scratch,
      CellRhs                                              &copy);

    // simulator_implicit.cc
    /// The cell matrix, right-hand side and values of a pass of
    /// assemble_implicit_system() over the cells.
    struct ImplicitCellData;
    void
    assemble_implicit_system(const double time);
    void
    assemble_implicit_cell(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const double                                          k,
      AssemblyScratch                                      &scratch,
      ImplicitCellData                                     &data);
    void
    solve_increment_implicit(const double time);
    /// Solves for a Newton correction, adds it to du and returns its norm.
    double
    apply_newton_correction(const double time, const unsigned int iteration);

    // simulator_stress.cc
    void
    update_stress(const unsigned int n);
    /// The stress update of chunk @p c of the cells (see stress_chunks)
    /// from the local entries of the increment and, for the implicit
    /// update, of the solution (else nullptr), as
    /// CellKinematics::local_entries() gives them; returns its largest
    /// stress component (infinity for NaN).
    double
    update_stress_chunk(const unsigned int  c,
                        const double *const increment_entries,
                        const double *const solution_entries = nullptr);
    /// In the second thread, after the substitutions beside the damage
    /// step: the increment from the solved block, then stress chunks until
    /// the damage step is done (stress_ahead).
    void
    update_stress_ahead(const double *const increment_entries);
    void
    compute_cell_stresses(Vector<double>              &von_mises,
                          std::vector<Vector<double>> &components) const;
    /// What every step reports of the state at its end (measure_step()).
    struct StepMeasures
    {
      double von_mises_max    = 0;
      double u_max            = 0;
      double energy           = 0;
      double damaged_fraction = 0;
      bool   u_finite         = true;
      bool   zeta_finite      = true;
    };
    StepMeasures
    measure_step() const;
    /// What the reports of a step (step_reports) read.
    struct StepReport
    {
      unsigned int                       n;
      double                             time;
      double                             u_max;
      const std::vector<Vector<double>> &components;
      StepQuantities                     quantities;
    };
    /// The partial sums of measure_step() over one chunk of the cells.
    struct StepSums
    {
      double von_mises_max = 0, u_square_max = 0, energy = 0, damaged = 0,
             volume = 0;
      // std::max() passes NaN by: it is counted apart.
      bool u_finite = true, zeta_finite = true;
    };
    void
    measure_chunk(const unsigned int  c,
                  const double *const entries,
                  StepSums           &sums) const;
    void
    check_finite(const StepMeasures &measures, const unsigned int n) const;
    double
    stress_error(const double time) const;

    // simulator_output.cc
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

    // The physics modules, each owning its section of the parameter file.
    Geometry<dim>                         geometry;
    ElasticMaterial<dim>                  material;
    ViscoplasticityParameters<dim>        viscoplasticity;
    std::unique_ptr<ViscoplasticLaw<dim>> viscoplastic_law;
    DamageModel<dim>                      damage_model;
    BoundaryConditions<dim>               boundary_conditions;
    TrescaFriction<dim>                   friction;
    /// Tresca friction (scenes with a contact boundary and a bound g > 0).
    std::unique_ptr<FrictionProblem<dim>> friction_problem;
    InitialConditions                     initial_conditions;
    TimeDiscretization                    time_discretization;
    IncrementPredictor                    increment_predictor;
    OutputWriter<dim>                     output_writer;
    Verification<dim>                     verification;
    MonitorPoints<dim>                    monitor_points;
    ConvergenceStudy<dim>                 convergence_study;
    ErrorEstimator<dim>                   error_estimator;
    /// The diagonal of the body's bounding box, the scale of the
    /// displacement safeguard in check_finite().
    double        body_size = 0;
    Checkpointing checkpointing;
    /// The checkpoint a resumed run reads (found by load_checkpoint_mesh()).
    CheckpointMetadata resumed_checkpoint;

    /// The element and rules of the mesh's cell type (Q1 or P1).
    const Discretization<dim> discretization;
    /// A p4est mesh of quadrilaterals (hexahedra), or a METIS-partitioned
    /// shared mesh of triangles (tetrahedra).
    const std::unique_ptr<parallel::TriangulationBase<dim>> mesh;
    parallel::TriangulationBase<dim>                       &triangulation;
    /// The displacement, and a damage component in damage scenes only.
    const FESystem<dim> &fe;
    /// The rule of assembly, stress storage and stress output alike.
    const Quadrature<dim> &quadrature;
    /// The linear mapping of the cells (MappingQ1 or MappingFE).
    const Mapping<dim> &mapping;
    DoFHandler<dim>     dof_handler;
    IndexSet            locally_owned_dofs;
    IndexSet            locally_relevant_dofs;
    /// Constraints on the increment du of the current step.
    AffineConstraints<double> constraints;

    /// K du = b on the displacement block, and its solver.
    DisplacementSystem displacement;
    /// u_n: owned part, in the blocks (displacement, damage), and a
    /// ghosted copy on all degrees of freedom for evaluation and output
    /// (one array of local entries, which CellKinematics reads).
    LA::MPI::BlockVector solution_owned;
    LA::MPI::Vector      solution;
    /// du = u_n - u_{n-1}: owned part, whose displacement block is the
    /// linear solver's vector, and its ghosted copy.
    LA::MPI::BlockVector increment_owned;
    LA::MPI::Vector      increment;
    /// The copies of both into their ghosted vectors, with the import kept
    /// (deal.II 9.4's assignment builds one per call; see GhostExchange).
    GhostExchange ghosts;

    StressHistory<dim> stress_history;

    /// Shape gradients, points and vector positions of every locally owned
    /// cell, for the passes over all cells in every step (once per mesh).
    CellKinematics<dim> cell_kinematics;
    /// The locally owned cells, for the passes over all of them in every
    /// step, which split them into stress_chunks chunks for the threads.
    std::vector<typename DoFHandler<dim>::active_cell_iterator> owned_cells;
    static constexpr unsigned int stress_chunks = 64;
    /// The owned cells in chunks and colors for the right-hand side's
    /// threads (made again when the constrained entries change).
    ConflictFreeChunks rhs_chunks;
    /// The stress chunks done ahead in the second thread, and the largest
    /// stress component of every chunk (see update_stress()).
    WorkAhead           stress_ahead;
    std::vector<double> stress_chunk_largest;

    /// The damage problem, step 4 (damage scenes only).
    std::unique_ptr<DamageProblem<dim>> damage_problem;
    /// The physics objects this scene has (damage, friction): the
    /// simulator reports and checkpoints them through this list instead of
    /// testing for each.
    std::vector<Physics *> physics;
    /// What adds to a step's statistics row and screen line, in the order
    /// of the columns: the physics objects and the comparisons with exact
    /// and reference solutions (collect_step_reports()).
    std::vector<std::function<void(std::string &, const StepReport &)>>
      step_reports;

    Statistics   statistics;
    unsigned int last_linear_iterations = 0;
  };
} // namespace VPContact

#endif
