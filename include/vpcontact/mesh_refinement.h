// Refinement between runs: the section "Mesh refinement" (how many cycles,
// uniform or adaptive, by which criterion), the error indicators accumulated
// over a run, and the next mesh and time step they lead to.
#ifndef vpcontact_mesh_refinement_h
#define vpcontact_mesh_refinement_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <set>

namespace VPContact
{
  using namespace dealii;

  /**
   * Per-cell error indicators of one run, accumulated over its time steps.
   *
   * At every step the Kelly estimator gives, for each cell K, the jumps of
   * the normal derivatives of the displacement (eta_u) and, in damage
   * scenes, of the damage (eta_zeta) across K's faces. They are combined in
   * the units of the error of the paper's Theorem 2,
   *   ||eps(u - u_h)||_Q + ||sigma - sigma_h||_Q + ||zeta - zeta_h||_L2,
   * as eta_K = (1 + E) eta_u + h_K eta_zeta: the strain error is of the
   * size of the gradient jumps, the stress error is E times that (sigma_h =
   * E eps(u_h) plus a history that is smooth within a cell), and the L2
   * error of the damage is one power of h below its gradient error.
   *
   * The indicator of a run is the largest over its steps, eta_K = max_n
   * eta_K,n: the theorem bounds the error at the worst time, and fronts that
   * move (the damage front, the slip front) leave a trace on every cell
   * they cross, which an indicator taken at the final time alone forgets.
   */
  template <int dim>
  class ErrorIndicator
  {
  public:
    /// Zero indicators for the active cells of the current mesh.
    void
    reinit(const Triangulation<dim> &triangulation);

    /**
     * Add step n: the Kelly indicators of the ghosted @p solution (the
     * displacement in the first dim components, the damage in component dim
     * when @p with_damage), weighted by the stiffness scale @p youngs_modulus.
     */
    void
    accumulate(const DoFHandler<dim>               &dof_handler,
               const TrilinosWrappers::MPI::Vector &solution,
               const bool                           with_damage,
               const double                         youngs_modulus);

    /// max_n eta_K,n on the locally owned cells (0 elsewhere).
    const Vector<float> &
    values() const;

  private:
    Vector<float> accumulated;
  };



  /**
   * Section "Mesh refinement": a sequence of runs ("cycles") over the whole
   * time interval, each on a mesh refined from the previous one.
   *
   * Every cycle starts again from t = 0: the scheme is a march in time, and
   * its error at t_n depends on the whole path, so a mesh is judged by the
   * run on it. Meshes of all cycles are refinements of the same coarse mesh
   * (Geometry), which is what makes errors against a reference run exact
   * (see ReferenceSolution).
   */
  template <int dim>
  class MeshRefinement
  {
  public:
    enum class Strategy
    {
      uniform,
      adaptive
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    unsigned int
    n_cycles() const;

    /**
     * The refinements of the finest mesh of the run, for a coarse mesh
     * refined @p global_refinements times: one more per uniform cycle.
     * Throws a message naming the entries if the cycles would go beyond
     * Maximum level, or if adaptive cycles start at it (they would repeat
     * the same run).
     */
    unsigned int
    finest_refinements(const unsigned int global_refinements) const;
    /// Whether the run needs error indicators (adaptive, more than one
    /// cycle).
    bool
    needs_indicators() const;

    /**
     * The number of times the time step of the parameter file is halved in
     * a cycle whose mesh has the equivalent size @p h, when the first cycle
     * had @p h_first: with "Refine time step with mesh", the nearest integer
     * to log2(h_first / h) (k proportional to h, kept on the dyadic grid
     * T / (N 2^j) so that every cycle shares the time levels of the first
     * one), else 0.
     */
    unsigned int
    time_step_halvings(const double h_first, const double h) const;

    /**
     * Refine @p triangulation for the next cycle: globally (uniform), or by
     * the indicators @p indicators (adaptive), never beyond Maximum level.
     * Cells on the boundaries in @p uniform_boundary_ids (the contact
     * boundary) are kept at one level among themselves, so that the nodal
     * Tresca conditions never meet a hanging node.
     */
    void
    refine(parallel::distributed::Triangulation<dim> &triangulation,
           const Vector<float>                       &indicators,
           const std::set<types::boundary_id> &uniform_boundary_ids) const;

    /// A one-line description for the screen.
    std::string
    description() const;

  private:
    void
    flag_adaptively(parallel::distributed::Triangulation<dim> &triangulation,
                    const Vector<float> &indicators) const;

    unsigned int cycles           = 1;
    Strategy     refinement       = Strategy::uniform;
    bool         fixed_fraction   = true;
    double       refine_fraction  = 0.3;
    double       coarsen_fraction = 0.;
    unsigned int maximum_level    = 10;
    bool         refine_time_step = true;
  };

  /// The equivalent mesh size (|Omega| / number of cells)^(1/dim), the cell
  /// side of a uniform mesh of squares with as many cells.
  template <int dim>
  double
  equivalent_mesh_size(const parallel::distributed::Triangulation<dim> &tria);
} // namespace VPContact

#endif
