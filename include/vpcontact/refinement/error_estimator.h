// The a posteriori estimate of a run's error in the norm of the paper's
// Theorem 2, computed after every step: a space part from the recovery of
// the stress, the strain and the damage gradient, and a time part from the
// quadrature error of the forward Euler step (doc/convergence.md).
#ifndef vpcontact_error_estimator_h
#define vpcontact_error_estimator_h

#include <vpcontact/fe/cell_kinematics.h>
#include <vpcontact/fe/conflict_free_chunks.h>
#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/fe/scalar_node_space.h>
#include <vpcontact/material/viscoplastic_law.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /// An estimate of the error of Theorem 2 at one time, or its largest
  /// over the steps: a space part and a time part.
  struct ErrorEstimate
  {
    double space = 0;
    double time  = 0;
    /// The estimate relative to the discrete solution's own size in the
    /// same norm, ||eps(u_h)|| + ||sigma_h|| + ||zeta_h||, at the same step
    /// (0 for a zero solution).
    double relative = 0;
    double
    sum() const
    {
      return space + time;
    }
  };

  /**
   * The estimate of the error of the discrete solution at t_n in the norm
   * of Theorem 2,
   *   ||eps(u_n - u_n^hk)|| + ||sigma_n - sigma_n^hk|| + ||zeta_n -
   *   zeta_n^hk||,
   * and its largest over the steps.
   *
   * Space part (Zienkiewicz-Zhu): the stress, the strain and the damage
   * gradient, which jump between cells, are projected onto continuous Q1
   * fields (an L2 projection with the lumped mass; at hanging nodes, the
   * constraints of the mesh). The distance between the recovered field and
   * the discrete one estimates the error of each: ||sigma* - sigma_h||,
   * ||eps* - eps(u_h)|| and, for the damage, whose L2 error is one power of
   * h below its gradient's, (h_K / pi) ||g* - grad zeta_h|| on each cell.
   *
   * Time part: the elastic part of the stress update is exact in time; the
   * forward Euler step integrates the viscoplastic rate by the left
   * rectangle rule, whose error at t_n is (k/2)(G(t_n) - G(0)) + O(k^2).
   * The time part is its L2 norm, (k/2) ||G_n - G_0||, times (1 + 1/E):
   * equilibrium passes at most that stress error on to the strain, divided
   * by E.
   *
   * The per-cell space indicators (largest over the steps) drive adaptive
   * refinement; the time part chooses the next cycle's time step.
   */
  template <int dim>
  class ErrorEstimator
  {
  public:
    using cell_iterator = typename DoFHandler<dim>::active_cell_iterator;

    /// Section "Error estimate".
    static void
    declare_parameters(ParameterHandler &prm);
    /// @p for_adaptive_cycles: the run refines by the cell indicators (then
    /// the estimate may not be switched off).
    void
    parse_parameters(ParameterHandler &prm, const bool for_adaptive_cycles);

    /// Whether the run estimates its error.
    bool
    is_active() const;

    /// Whether step @p n of a run of @p n_steps steps is estimated (see
    /// the entry "Every steps").
    bool
    estimates_step(const unsigned int n, const unsigned int n_steps) const;

    /**
     * On a new mesh: the recovery space and its lumped mass, for the
     * locally owned cells @p owned_cells and the data of @p kinematics and
     * @p history. The space is @p nodes if given (the damage block), else
     * a scalar Q1 (P1) space of its own on @p triangulation. All must stay
     * valid until the next setup().
     */
    void
    setup(const parallel::TriangulationBase<dim> &triangulation,
          const std::vector<cell_iterator>       &owned_cells,
          const CellKinematics<dim>              &kinematics,
          StressHistory<dim>                     &history,
          const ScalarNodeSpace<dim>             *nodes = nullptr);

    /**
     * The estimate at t_n, for the step size @p k and the local entries
     * @p entries of the ghosted solution u_n (and zeta_n, in damage
     * scenes); at n = 0 it stores the initial rate G_0 at every point.
     * Collective.
     */
    ErrorEstimate
    estimate_step(const unsigned int          n,
                  const double                k,
                  const double               *entries,
                  const ViscoplasticLaw<dim> &law,
                  const double                youngs_modulus);

    /// The estimate whose sum is the largest over the steps so far.
    ErrorEstimate
    largest() const;

    /// max_n of each part on its own, and of the relative estimate.
    ErrorEstimate
    largest_parts() const;

    /// max_n of the space indicator of each locally owned cell.
    const Vector<float> &
    cell_indicators() const;

    /// The space indicator of each locally owned cell at the last step
    /// estimated (what an adaptation during the run refines by).
    const Vector<float> &
    last_step_indicators() const;

    /// The largest values so far, for a checkpoint.
    std::map<std::string, double>
    running_maxima() const;
    void
    restore_running_maxima(const std::map<std::string, double> &maxima);

  private:
    /// The most quadrature points and nodes per cell (the 2^dim Gauss
    /// points and vertices of Q1).
    static constexpr unsigned int max_points = 8;
    static constexpr unsigned int max_nodes  = 8;
    /// The squared norms of one cell, for the sums of the space and time
    /// parts.
    struct CellNorms
    {
      double stress = 0, strain = 0, damage = 0, time = 0;
      /// The squared norms of sigma_h, eps(u_h) and zeta_h on the cell.
      double solution_stress = 0, solution_strain = 0, solution_damage = 0;

      CellNorms &
      operator+=(const CellNorms &other)
      {
        stress += other.stress;
        strain += other.strain;
        damage += other.damage;
        time += other.time;
        solution_stress += other.solution_stress;
        solution_strain += other.solution_strain;
        solution_damage += other.solution_damage;
        return *this;
      }
    };
    void
    make_own_space(const parallel::TriangulationBase<dim> &triangulation);
    void
    setup_nodes_and_mass(std::vector<unsigned int> &positions,
                         std::vector<bool>         &plain);
    void
    setup_chunks(std::vector<unsigned int> &&positions,
                 const std::vector<bool>    &plain);
    void
    setup_hanging_nodes();
    void
    setup_cell_data();
    template <bool damage>
    void
    evaluate_fields(const std::size_t        i,
                    const double            *entries,
                    SymmetricTensor<2, dim> *strain,
                    Tensor<1, dim>          *gradient,
                    double                  *zeta) const;
    /// The recovered fields at the points of cell @p i into @p f, and the
    /// strain and damage there (see the definition).
    template <bool damage>
    void
    point_values(const std::size_t        i,
                 const double            *entries,
                 double                  *f,
                 SymmetricTensor<2, dim> *strain,
                 double                  *zeta) const;
    template <bool damage>
    CellNorms
    first_pass(const std::size_t           i,
               const double               *entries,
               const ViscoplasticLaw<dim> &law,
               const bool                  initial,
               double                     *moments);
    template <bool damage>
    void
    add_plain_moments(const unsigned int          color,
                      const double               *entries,
                      const ViscoplasticLaw<dim> &law,
                      const bool                  initial);
    void
    add_constrained_moments(const std::size_t i, const double *moments);
    void
    project_to_nodes();
    template <bool damage>
    CellNorms
    second_pass(const std::size_t i, const double *entries);
    template <bool damage>
    void
    passes(const unsigned int          n,
           const double               *entries,
           const ViscoplasticLaw<dim> &law);
    ErrorEstimate
    sum_norms(const double k, const double youngs_modulus);

    bool         active      = true;
    unsigned int every_steps = 1;

    const parallel::TriangulationBase<dim> *triangulation = nullptr;
    const std::vector<cell_iterator>       *cells         = nullptr;
    const CellKinematics<dim>              *kinematics    = nullptr;
    StressHistory<dim>                     *history       = nullptr;
    bool                                    with_damage   = false;
    /// The quadrature points and the nodes of a cell (the same on all).
    unsigned int n_q     = 0;
    unsigned int n_nodes = 0;
    /// The number of recovered components: the stress and the strain
    /// (n_independent_components each) and, with damage, the damage
    /// gradient (dim).
    unsigned int n_components = 0;

    /// The recovery space: given, or made here (then on recovery_dofs,
    /// with the scalar element of the mesh's cells, Q1 or P1, and the
    /// constraints own_constraints).
    ScalarNodeSpace<dim>                space;
    std::unique_ptr<FiniteElement<dim>> recovery_fe;
    DoFHandler<dim>                     recovery_dofs;
    AffineConstraints<double>           own_constraints;
    /// The recovered fields in one ghosted vector, all components of a node
    /// side by side: node j's (scalar local index) component c at local
    /// entry j * n_components + c. One exchange per step moves them all,
    /// and a cell reads one cache line per node. Its layout is kept for
    /// the mesh; with Every steps > 1 the vector holds memory only while a
    /// step is estimated (16.8 MB at 512^2 cells with damage), not while
    /// the fields of that step are written after it, where a run's memory
    /// peaks.
    dealii::LinearAlgebra::distributed::Vector<double> recovered;
    std::shared_ptr<const Utilities::MPI::Partitioner> recovered_layout;
    dealii::LinearAlgebra::distributed::Vector<double> lumped_mass;
    /// The nodes of each owned cell by global index (their positions in the
    /// local storage of the scalar layout are the plan's positions()).
    std::vector<types::global_dof_index> node_indices;
    /// The owned cells in chunks of consecutive cells, and the chunks in
    /// colors whose cells without hanging nodes share no node: the first
    /// pass adds their moments to the recovered fields from several
    /// threads at once. The cells with hanging nodes are its other cells.
    ConflictFreeChunks chunks;
    /// The constrained nodes of the owned cells (scalar local indices) and
    /// the nodes and weights they take their values from.
    std::vector<unsigned int>                    hanging_nodes;
    std::vector<unsigned int>                    hanging_start;
    std::vector<std::pair<unsigned int, double>> hanging_parents;
    /// (h_K / pi)^2 of each owned cell.
    std::vector<double> damage_weights;

    /// Per step: the norms summed over the cells of each chunk, in the
    /// cells' order, and (last) over the cells with hanging nodes.
    std::vector<CellNorms> chunk_norms;

    ErrorEstimate largest_sum, largest_part;
    Vector<float> indicators;
    Vector<float> step_indicators;
  };
} // namespace VPContact

#endif
