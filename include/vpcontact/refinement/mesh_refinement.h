// Refinement between runs and during a run: the section "Mesh refinement"
// (how many cycles, uniform or adaptive, by which criterion, whether and how
// often the mesh adapts during a run), and the flags that the error
// indicators lead to.
#ifndef vpcontact_mesh_refinement_h
#define vpcontact_mesh_refinement_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <set>

namespace VPContact
{
  using namespace dealii;

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
    static void
    declare_time_step_entries(ParameterHandler &prm);
    /// The entries of the adaptation during a run, and the limits it
    /// shares with adaptive cycles (mesh_refinement_during_run.cc).
    static void
    declare_run_entries(ParameterHandler &prm);
    /// @p base_level: the level of the cells of Geometry's coarse mesh as
    /// the user defines it (Geometry::base_level()), from which Maximum
    /// level and Minimum level count.
    void
    parse_parameters(ParameterHandler &prm, const unsigned int base_level);

    unsigned int
    n_cycles() const;

    /**
     * The largest number of cells of a mesh of the run relative to the
     * first one (that of Geometry/Global refinements = @p
     * global_refinements): 2^dim per uniform cycle; for adaptive cycles the
     * most that the Refinement fraction ('fixed number', or 'fixed
     * fraction' = 1) and Maximum level allow, else 1 (refine() checks the
     * memory before each adaptive refinement). Throws a message naming the
     * entries if uniform cycles would go beyond Maximum level, or if
     * adaptive cycles start at it (they would repeat the same run).
     */
    double
    largest_growth(const unsigned int global_refinements) const;

    /// The entries that set the size of the cycles' meshes, for messages
    /// (", Mesh refinement/Number of cycles = 4 ..."); empty with one cycle.
    std::string
    size_entries() const;

    /// Whether the run needs error indicators (adaptive, more than one
    /// cycle; or adapting during the run).
    bool
    needs_indicators() const;

    /// Whether the mesh adapts during the run (Adapt during run).
    bool
    adapts_during_run() const;

    /// The steps between two adaptations during the run (Adapt every).
    unsigned int
    adapt_every() const;

    /// The adaptations to the initial state before the first step (Initial
    /// adaptations; 0 unless the mesh adapts during the run).
    unsigned int
    initial_adaptations() const;

    /// Whether the mesh adapts after step @p n of a run of @p n_steps
    /// steps: every Adapt every steps, never after step 0 or the last.
    bool
    adapts_after_step(const unsigned int n, const unsigned int n_steps) const;

    /**
     * Flag the cells of @p triangulation for an adaptation during the run
     * by the indicators @p indicators, as refine() flags them for an
     * adaptive cycle; returns whether any cell is flagged (on any rank).
     * The caller executes the change.
     */
    bool
    flag_for_adaptation(
      parallel::TriangulationBase<dim>   &triangulation,
      const Vector<float>                &indicators,
      const std::set<types::boundary_id> &uniform_boundary_ids) const;

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

    /// Whether adaptive cycles choose their time step from the error
    /// estimate of the previous cycle (see ConvergenceStudy::start_cycle()).
    bool
    time_step_from_estimate() const;

    /**
     * Refine @p triangulation for the next cycle: globally (uniform), or by
     * the indicators @p indicators (adaptive), never beyond Maximum level.
     * Cells on the boundaries in @p uniform_boundary_ids (the contact
     * boundary) are kept at one level among themselves, so that the nodal
     * Tresca conditions never meet a hanging node.
     */
    void
    refine(parallel::TriangulationBase<dim>   &triangulation,
           const Vector<float>                &indicators,
           const std::set<types::boundary_id> &uniform_boundary_ids) const;

    /// A one-line description for the screen.
    std::string
    description() const;

    /// A one-line description of the adaptation during the run, or "".
    std::string
    run_description() const;

  private:
    /// The flags of an adaptive refinement, contact cells at one level and
    /// the memory of the next mesh checked.
    void
    flag_cells(parallel::TriangulationBase<dim>   &triangulation,
               const Vector<float>                &indicators,
               const std::set<types::boundary_id> &uniform_boundary_ids,
               const std::string                  &what,
               const bool same_on_any_ranks = false) const;
    /**
     * The flags of flag_adaptively() from all ranks' indicators sorted
     * (mesh_refinement_during_run.cc): the same cells on any number of
     * ranks, which deal.II's distributed marking, a bisection for the
     * threshold, does not promise.
     */
    void
    flag_by_sorted_indicators(parallel::TriangulationBase<dim> &triangulation,
                              const Vector<float> &indicators) const;
    void
    flag_adaptively(parallel::TriangulationBase<dim> &triangulation,
                    const Vector<float>              &indicators) const;
    /// No refinement beyond Maximum level, no coarsening below Minimum
    /// level.
    void
    clear_flags_beyond_levels(
      parallel::TriangulationBase<dim> &triangulation) const;
    /// Refine only the cells with the largest indicators that keep the
    /// mesh within Maximum cells.
    void
    keep_within_budget(parallel::distributed::Triangulation<dim> &triangulation,
                       const Vector<float> &indicators) const;

    /// Throw a message naming the entries if the mesh that the refinement
    /// flags of @p triangulation make cannot fit in memory.
    void
    check_memory_of_next_mesh(
      const parallel::TriangulationBase<dim> &triangulation,
      const std::string                      &what) const;

    unsigned int cycles           = 1;
    Strategy     refinement       = Strategy::uniform;
    bool         fixed_fraction   = true;
    double       refine_fraction  = 0.3;
    double       coarsen_fraction = 0.;
    unsigned int maximum_level    = 10;
    unsigned int minimum_level    = 0;
    /// See parse_parameters().
    unsigned int base_level         = 0;
    unsigned int maximum_cells      = 0;
    bool         during_run         = false;
    unsigned int every_steps        = 10;
    unsigned int n_initial          = 0;
    bool         refine_time_step   = true;
    bool         step_from_estimate = false;
  };

  /// The equivalent mesh size (|Omega| / number of cells)^(1/dim), the cell
  /// side of a uniform mesh of squares with as many cells.
  template <int dim>
  double
  equivalent_mesh_size(const parallel::TriangulationBase<dim> &tria);
} // namespace VPContact

#endif
