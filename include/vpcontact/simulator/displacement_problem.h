// The displacement problem of the paper's scheme (steps 1-3): the
// predictor and right-hand side, the stick/slip active set around the
// linear solves of the increment, and the stress update at the quadrature
// points, with everything they keep: constraints, matrix, u_n and du, the
// stress history, and Tresca friction where the scene has it.
#ifndef vpcontact_displacement_problem_h
#define vpcontact_displacement_problem_h

#include <vpcontact/contact/friction_problem.h>
#include <vpcontact/contact/tresca_friction.h>
#include <vpcontact/fe/cell_kinematics.h>
#include <vpcontact/fe/conflict_free_chunks.h>
#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/material/elastic_material.h>
#include <vpcontact/material/viscoplastic_law.h>
#include <vpcontact/problem_data/boundary_conditions.h>
#include <vpcontact/simulator/displacement_system.h>
#include <vpcontact/simulator/increment_predictor.h>
#include <vpcontact/simulator/simulator_access.h>
#include <vpcontact/simulator/work_ahead.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /// What every step reports of the state at its end
  /// (DisplacementProblem::measure_step()).
  struct StepMeasures
  {
    double von_mises_max    = 0;
    double u_max            = 0;
    double energy           = 0;
    double damaged_fraction = 0;
    bool   u_finite         = true;
    bool   zeta_finite      = true;
  };



  /**
   * The quasistatic displacement problem of the paper's scheme (14), steps
   * 1-3, in the manner of deal.II's step-40 and step-42. A step solves for
   * the increment du = u_n - u_{n-1} = k w (the paper's velocity problem
   * multiplied by k, so the matrix is E and does not depend on k):
   *
   *   (E eps(du), eps(v)) = (f_n, v) - (sigma_{n-1} + k G_{n-1}, eps(v)),
   *
   * then sets sigma_n = sigma_{n-1} + k G_{n-1} + E eps(du). With Tresca
   * friction (a contact boundary and g > 0) it owns the FrictionProblem
   * and runs the stick/slip active set around the solves, in one loop
   * (finish_increment()).
   *
   * It owns the sections "Elasticity", "Viscoplasticity", "Boundary
   * conditions" and "Contact", the displacement entries of "Solver", and
   * the fields of the displacement block: u_n and du in blocks
   * (displacement, damage) with their ghosted copies, the stress history,
   * the constraints of du, the matrix and its solver. The damage block of
   * u_n belongs to the DamageProblem, which reads and writes it through
   * solution_blocks().
   *
   * The implementation is split by concern:
   * - displacement_problem.cc: parameters, setup on a mesh, constraints;
   * - displacement_assembly.cc: the stiffness matrix and the right-hand
   *   side;
   * - displacement_solve.cc: the active-set loop around the solves;
   * - displacement_implicit.cc: the backward Euler alternative;
   * - displacement_stress.cc: the stress update, its safeguards and the
   *   quantities output reads.
   */
  template <int dim>
  class DisplacementProblem : private SimulatorAccess<dim>
  {
  public:
    using cell_iterator = typename DoFHandler<dim>::active_cell_iterator;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Read the sections it owns; @p access must outlive this object.
    DisplacementProblem(ParameterHandler           &prm,
                        const SimulatorAccess<dim> &access);

    /// Releases the linear solver before the matrix it refers to.
    ~DisplacementProblem();

    /// Refuse an explicit step beyond the law's stability limit.
    void
    check_stability_limits() const;

    /**
     * On a new mesh (its boundary ids checked first, against the entries
     * and, for a mesh from a file, @p mesh_source, for ids no entry names):
     * Tresca friction where the contact boundary has g > 0 somewhere over
     * the run (else none). Returns the FrictionProblem, or nullptr, for the
     * simulator's list of physics objects.
     */
    Physics<dim> *
    setup_contact(const std::string &mesh_source);

    /// On new degrees of freedom: constraints, the matrix's sparsity, the
    /// contact nodes, the check that the body is held, and the vectors.
    void
    setup_dofs();

    /// sigma_0 = 0 at the points of the owned cells, their JxW, and the
    /// cells' kinematics.
    void
    setup_stress_history();

    void
    assemble_stiffness_matrix();

    /**
     * The displacement increment of the step at @p time, u_n = u_{n-1} +
     * du, in two calls, so that the caller can do other work beside the
     * first solve. begin_increment() assembles the first right-hand side
     * and, with @p work_beside where the linear solver allows it
     * (LinearSolver::solves_in_background()), starts that solve's
     * substitutions in a second thread; finish_increment() waits for them
     * (or solves) and runs the rest of the stick/slip active set. The work
     * between the two must not touch this object's vectors or solver, and
     * must read nothing that the later iterations change.
     */
    void
    begin_increment(const double time,
                    const bool   with_viscoplastic_rate,
                    const bool   work_beside);
    /// See begin_increment(); the same arguments but @p work_beside.
    void
    finish_increment(const double time, const bool with_viscoplastic_rate);
    /// Instead of finish_increment() where the work beside failed: wait
    /// for the second thread, which writes the increment and the stress.
    void
    abandon_increment();
    /// begin_increment() and finish_increment() with nothing between.
    void
    solve_increment(const double time, const bool with_viscoplastic_rate);
    /// The backward Euler alternative to solve_increment() (Newton's
    /// method on the whole step).
    void
    solve_increment_implicit(const double time);
    /**
     * Build the preconditioner or factors of the displacement matrix; with
     * @p in_background, a factorization on one process runs in a second
     * thread (LinearSolver::initialize_in_background()) and the first solve
     * waits for it. Until then the matrix must not change.
     */
    void
    initialize_linear_solver(const bool in_background = false);
    void
    report_solve_floor();

    /// The stress update of step @p n.
    void
    update_stress(const unsigned int n);

    /// The constraints of du at @p time, inhomogeneous ones from the
    /// ghosted displacement @p previous (u_{n-1}) where there are
    /// prescribed displacements or unilateral contact; the stick nodes'
    /// only @p with_stick.
    void
    make_constraints(const double           time,
                     const LA::MPI::Vector *previous,
                     const bool             with_stick = true);

    void
    compute_cell_stresses(Vector<double>              &von_mises,
                          std::vector<Vector<double>> &components) const;
    StepMeasures
    measure_step() const;

    /// The largest |u| a sound run reaches: Viscoplasticity/Divergence
    /// limit times the diagonal of the body's bounding box.
    double
    displacement_limit() const;

    /// Whether the viscoplastic step is backward Euler.
    bool
    implicit() const;

    /// u_n in blocks (displacement, damage): the damage problem reads
    /// zeta_{n-1} from block 1 and stores zeta_n there, then calls
    /// update_ghosted_solution().
    LA::MPI::BlockVector &
    solution_blocks();
    void
    update_ghosted_solution();
    /// u_n with the ghost entries of the owned cells' nodes.
    const LA::MPI::Vector &
    ghosted_solution() const;
    /// du, owned in blocks and ghosted.
    LA::MPI::BlockVector &
    increment_blocks();
    const LA::MPI::Vector &
    ghosted_increment() const;

    StressHistory<dim> &
    history();
    const StressHistory<dim> &
    history() const;
    const CellKinematics<dim> &
    kinematics() const;
    const std::vector<cell_iterator> &
    cells() const;

    const ElasticMaterial<dim> &
    elastic_material() const;
    const ViscoplasticityParameters<dim> &
    viscoplasticity_parameters() const;
    const ViscoplasticLaw<dim> &
    law() const;
    const BoundaryConditions<dim> &
    boundaries() const;
    /// The contact condition in words, for the run's header.
    std::string
    contact_description() const;
    /// The friction problem, or nullptr where the scene has none.
    const FrictionProblem<dim> *
    contact() const;
    FrictionProblem<dim> *
    contact();
    IncrementPredictor &
    predictor();
    /// The displacement's linear solver (the damage problem takes its
    /// package).
    const LinearSolver &
    solver() const;

    /// For a checkpoint: du_n, du_{n-1} and du_{n-2} on all degrees of
    /// freedom, ghosted.
    std::array<LA::MPI::Vector, 3>
    increments_for_checkpoint();
    /// From a checkpoint: u_n, du_n, du_{n-1} and du_{n-2}, owned, on all
    /// degrees of freedom.
    void
    restore_fields(const std::array<LA::MPI::Vector, 4> &full);
    /// After restore_fields() and the friction sets: the constraints at
    /// @p time and the predictor's count of increments.
    void
    resume_at(const double time, const unsigned int n_recorded);
    /// The predictor's count of increments and the automatic solver
    /// choice's state, as checkpoint counters.
    std::map<std::string, double>
    checkpoint_counters() const;
    /// That state from a checkpoint's counters (none: a new run's).
    void
    restore_solver_choice(const std::map<std::string, double> &counters);

    /// The linear solver's iterations in the last step.
    unsigned int
    linear_iterations() const;
    /// Forget the counts of an earlier run (a new cycle).
    void
    reset_linear_iterations();

  private:
    /// The displacement block [0, n_u) of the block numbering, and the
    /// solver for its size (Linear solver = automatic).
    void
    setup_block_views();

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

    void
    solve_displacement();
    /// The first solve of a step: started in the second thread (see
    /// begin_increment()), or left to complete_first_solve().
    void
    start_first_solve(const bool work_beside);
    void
    complete_first_solve();
    /// Wait for factors begun in the background, timed as building them.
    void
    wait_for_linear_solver();
    /// After a solve: the constrained entries of du, and its ghosted copy.
    void
    share_increment();
    bool
    friction_sets_settled(const double time, const unsigned int iteration);
    /// Before a factorization anew for a changed stick set at @p time.
    void
    note_refactorization(const double time);
    /// Whether the solves of a friction iteration may stop at the square
    /// root of the tolerance while the sets change.
    bool
    may_solve_loosely() const;
    /// Whether the first solve of a step will turn slip directions, so
    /// that more solves follow it in any case.
    bool
    first_solve_turns_directions() const;

    /// Stop if the active set cycles or does not settle in the entries'
    /// number of iterations.
    void
    check_sets_settle(
      const double                                    time,
      const unsigned int                              iteration,
      const typename FrictionActiveSet<dim>::Changes &changes) const;
    const LA::MPI::Vector &
    assemble_contact_residual();

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
    /// Solves for a Newton correction, adds it to du and returns its norm.
    double
    apply_newton_correction(const double time, const unsigned int iteration);


    /// What a pass over the stress at the points of a chunk of the cells
    /// finds: its largest component (infinity for NaN), and for
    /// measure_step() the energy stored in it and the largest von Mises
    /// stress of the cell averages.
    struct StressSums
    {
      double largest = 0, energy = 0, von_mises_max = 0;
    };
    /// The stress update of chunk @p c of the cells (see stress_chunks)
    /// from the local entries of the increment and, for the implicit
    /// update, of the solution (else nullptr), as
    /// CellKinematics::local_entries() gives them; returns the new stress'
    /// StressSums.
    StressSums
    update_stress_chunk(const unsigned int  c,
                        const double *const increment_entries,
                        const double *const solution_entries = nullptr);
    /// In the second thread, after the substitutions beside the damage
    /// step: the increment from the solved block, then stress chunks until
    /// the damage step is done (stress_ahead).
    void
    update_stress_ahead(const double *const increment_entries);
    /// The StressSums of chunk @p c as the points hold them now.
    StressSums
    measure_stress_chunk(const unsigned int c) const;
    /// The damaged volume and the volume of chunk @p c of the cells, for
    /// the damage of the local @p entries of the solution.
    struct DamageSums
    {
      double damaged = 0, volume = 0;
      bool   zeta_finite = true;
    };
    DamageSums
    measure_damage_chunk(const unsigned int  c,
                         const double *const entries) const;
    /// The largest |u| of the local @p entries of the solution into
    /// @p measures.
    void
    measure_displacement(const double *const entries,
                         StepMeasures       &measures) const;

    /// Stop with a message if no contact node sticks and the other
    /// constraints leave the body a rigid motion.
    void
    check_held_while_slipping(const double time);
    void
    measure_body();
    void
    setup_displacement_matrix();
    void
    add_displacement_hanging_nodes();
    void
    setup_vectors();
    NearNullSpace
    rigid_motions() const;
    /// The displacement degrees of freedom of @p cell, in the order of
    /// displacement.shape_functions.
    void
    get_displacement_dof_indices(
      const cell_iterator                  &cell,
      std::vector<types::global_dof_index> &indices) const;

    // What the simulator shares (SimulatorAccess), by the names the
    // functions use.
    using SimulatorAccess<dim>::mpi_communicator;
    using SimulatorAccess<dim>::pcout;
    using SimulatorAccess<dim>::computing_timer;
    using SimulatorAccess<dim>::discretization;
    using SimulatorAccess<dim>::triangulation;
    using SimulatorAccess<dim>::fe;
    using SimulatorAccess<dim>::quadrature;
    using SimulatorAccess<dim>::mapping;
    using SimulatorAccess<dim>::dof_handler;
    using SimulatorAccess<dim>::locally_owned_dofs;
    using SimulatorAccess<dim>::locally_relevant_dofs;
    using SimulatorAccess<dim>::time_discretization;
    using SimulatorAccess<dim>::damage_model;
    using SimulatorAccess<dim>::output_writer;

    ElasticMaterial<dim>                  material;
    ViscoplasticityParameters<dim>        viscoplasticity;
    std::unique_ptr<ViscoplasticLaw<dim>> viscoplastic_law;
    BoundaryConditions<dim>               boundary_conditions;
    TrescaFriction<dim>                   friction;
    /// Tresca friction (scenes with a contact boundary and a bound g > 0).
    std::unique_ptr<FrictionProblem<dim>> friction_problem;
    /// The largest friction bound or Coulomb coefficient on the contact
    /// boundary over the run (0: frictionless).
    double largest_friction = 0;
    /// Whether the last active-set iteration kept a node in the stick set
    /// that would have slipped (check_held_while_slipping()).
    bool               kept_one_stick = false;
    IncrementPredictor increment_predictor;

    /// Constraints on the increment du of the current step (displacement
    /// block).
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
    std::vector<cell_iterator>    owned_cells;
    static constexpr unsigned int stress_chunks = 64;
    /// The owned cells in chunks and colors for the right-hand side's
    /// threads (made again when the constrained entries change).
    ConflictFreeChunks rhs_chunks;
    /// The stress chunks done ahead in the second thread, and the
    /// StressSums of every chunk (see update_stress()), which hold the
    /// stress at the points while stress_sums_current: update_stress() sets
    /// it, and setup_stress_history() and history() (write access to the
    /// points) clear it.
    WorkAhead               stress_ahead;
    std::vector<StressSums> stress_chunk_sums;
    bool                    stress_sums_current = false;

    /// The diagonal of the body's bounding box (displacement_limit()).
    double body_size = 0;
    /// r = b - A(du) on the contact cells, as assembled (with ghost
    /// entries), for the friction multipliers.
    LA::MPI::Vector contact_residual;

    unsigned int last_linear_iterations = 0;
    /// The substitutions of a step's first solve in the second thread,
    /// between begin_increment() and finish_increment(), where they run.
    std::future<unsigned int> first_solve;
    /// Whether the CG solves after a change of the friction sets may stop
    /// early in this step (see may_solve_loosely()).
    bool may_loosen = false;
    /// Whether this step's first solve stops early too (see
    /// first_solve_turns_directions()).
    bool loose_first = false;
  };
} // namespace VPContact

#endif
