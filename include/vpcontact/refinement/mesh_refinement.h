// Refinement between runs: the section "Mesh refinement" (how many cycles,
// uniform or adaptive, by which criterion), and the next mesh and time step
// that the error indicators of a run lead to.
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
    void
    parse_parameters(ParameterHandler &prm);

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

  private:
    void
    flag_adaptively(parallel::TriangulationBase<dim> &triangulation,
                    const Vector<float>              &indicators) const;

    /// Throw a message naming the entries if the mesh that the refinement
    /// flags of @p triangulation make cannot fit in memory.
    void
    check_memory_of_next_mesh(
      const parallel::TriangulationBase<dim> &triangulation) const;

    unsigned int cycles             = 1;
    Strategy     refinement         = Strategy::uniform;
    bool         fixed_fraction     = true;
    double       refine_fraction    = 0.3;
    double       coarsen_fraction   = 0.;
    unsigned int maximum_level      = 10;
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
