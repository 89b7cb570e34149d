// The simulator: owns the mesh, the degrees of freedom, the linear algebra
// and the physics modules, and calls them in the order of the paper's scheme.
#ifndef vpcontact_simulator_h
#define vpcontact_simulator_h

#include <vpcontact/boundary_conditions.h>
#include <vpcontact/elastic_material.h>
#include <vpcontact/geometry.h>
#include <vpcontact/linear_solver.h>
#include <vpcontact/output_writer.h>
#include <vpcontact/statistics.h>
#include <vpcontact/time_discretization.h>
#include <vpcontact/tresca_friction.h>
#include <vpcontact/verification.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * The quasistatic problem on a distributed mesh, in the manner of deal.II's
   * step-40 and step-42.
   *
   * The implementation is split by concern:
   * - simulator.cc: parameters, construction, the time loop;
   * - simulator_setup.cc: mesh, degrees of freedom, constraints, sparsity;
   * - simulator_assembly.cc: the stiffness matrix and the load vector;
   * - simulator_output.cc: stresses, statistics, screen and field output.
   *
   * The unknown is the displacement, Q1 in every component of one FESystem.
   * The physics of this release is linear elasticity: at every t_n the
   * displacement u_n solves (E eps(u_n), eps(v)) = (f_n, v) with the
   * boundary parts of BoundaryConditions.
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

    /// Run the scene from t = 0 to T.
    void
    run();

  private:
    // simulator_setup.cc
    void
    make_mesh();
    void
    setup_dofs();

    // simulator_assembly.cc
    void
    assemble_stiffness_matrix();
    void
    assemble_load_vector(const double time);

    // simulator.cc
    void
    solve_step(const unsigned int n);

    // simulator_output.cc
    void
    print_header() const;
    void
    postprocess_step(const unsigned int n, const double step_wall_time);
    void
    compute_cell_stresses(Vector<double>              &von_mises,
                          std::vector<Vector<double>> &components) const;
    void
    write_fields(const unsigned int                 n,
                 const Vector<double>              &von_mises,
                 const std::vector<Vector<double>> &components);
    void
    print_summary() const;

    MPI_Comm            mpi_communicator;
    ConditionalOStream  pcout;
    mutable TimerOutput computing_timer;

    // The physics modules, each owning its section of the parameter file.
    Geometry<dim>           geometry;
    ElasticMaterial<dim>    material;
    BoundaryConditions<dim> boundary_conditions;
    TrescaFriction<dim>     friction;
    TimeDiscretization      time_discretization;
    LinearSolver            linear_solver;
    OutputWriter<dim>       output_writer;
    Verification<dim>       verification;

    parallel::distributed::Triangulation<dim> triangulation;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;
    IndexSet                                  locally_owned_dofs;
    IndexSet                                  locally_relevant_dofs;
    AffineConstraints<double>                 constraints;

    TrilinosWrappers::SparseMatrix stiffness_matrix;
    TrilinosWrappers::MPI::Vector  load_vector;
    /// u_n on the locally owned dofs (the solver's vector).
    TrilinosWrappers::MPI::Vector displacement_owned;
    /// u_n with ghost entries, for evaluation and output.
    TrilinosWrappers::MPI::Vector displacement;

    Statistics   statistics;
    unsigned int last_linear_iterations = 0;
  };
} // namespace VPContact

#endif
