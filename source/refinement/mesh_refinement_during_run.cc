// The adaptation of the mesh during a run: the entries of the section "Mesh
// refinement" that ask for it, its schedule, and the flags of each
// adaptation (the cell budget included).
#include <vpcontact/input/input_error.h>
#include <vpcontact/refinement/mesh_refinement.h>

#include <deal.II/distributed/grid_refinement.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace VPContact
{
  template <int dim>
  void
  MeshRefinement<dim>::declare_run_entries(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry("Minimum level",
                        "0",
                        Patterns::Integer(0, 20),
                        "Adaptive only: no cell is coarsened to fewer levels "
                        "than this above the coarse mesh (the box of "
                        "Geometry/Subdivisions, or the mesh file's cells).");
      prm.declare_entry(
        "Maximum cells",
        "0",
        Patterns::Integer(0),
        "Adaptive only: a cell budget. Where the flags of Refinement "
        "criterion would make a mesh of more cells, only the cells with the "
        "largest indicators that keep it within the budget are refined "
        "(deal.II's refine_and_coarsen_fixed_number with max_n_cells). 0: "
        "no budget.");
      prm.declare_entry(
        "Adapt during run",
        "false",
        Patterns::Bool(),
        "Refine and coarsen the mesh during the run, after every 'Adapt "
        "every' steps, by the error estimate's cell indicators of that step "
        "(Refinement criterion, Refinement fraction, Coarsening fraction, "
        "Maximum level, Minimum level, Maximum cells); the displacement, the "
        "damage, their increments, the stress history at the quadrature "
        "points and the active sets are carried to the new mesh "
        "(doc/adaptivity.md). Needs a mesh of quadrilaterals (hexahedra) and "
        "Number of cycles = 1.");
      prm.declare_entry(
        "Initial adaptations",
        "0",
        Patterns::Integer(0, 20),
        "With Adapt during run: before the first step, adapt the mesh this "
        "many times to the error indicators of the initial state, computing "
        "the initial state again on each new mesh, so that the first steps "
        "already have the mesh the singularities of the initial state ask "
        "for (Initial state/Displacement and stress = elastic equilibrium; "
        "a zero initial state has no indicators and adapts nothing).");
      prm.declare_entry("Adapt every",
                        "10",
                        Patterns::Integer(1),
                        "With Adapt during run: the steps between two "
                        "adaptations. A multiple of Error estimate/Every "
                        "steps, so that the step of an adaptation is "
                        "estimated.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  bool
  MeshRefinement<dim>::adapts_during_run() const
  {
    return during_run;
  }



  template <int dim>
  unsigned int
  MeshRefinement<dim>::adapt_every() const
  {
    return every_steps;
  }



  template <int dim>
  unsigned int
  MeshRefinement<dim>::initial_adaptations() const
  {
    return during_run ? n_initial : 0;
  }



  template <int dim>
  bool
  MeshRefinement<dim>::adapts_after_step(const unsigned int n,
                                         const unsigned int n_steps) const
  {
    return during_run && n > 0 && n < n_steps && n % every_steps == 0;
  }



  template <int dim>
  bool
  MeshRefinement<dim>::flag_for_adaptation(
    parallel::TriangulationBase<dim>   &triangulation,
    const Vector<float>                &indicators,
    const std::set<types::boundary_id> &uniform_boundary_ids) const
  {
    // deal.II smooths the flags before the mesh changes. Of its smoothing
    // only the level difference at vertices is kept here: eliminating
    // unrefined islands looks at neighbours a rank may not see, and in 3D
    // it gave meshes of 834 and 827 cells on 1 and 2 ranks from the same
    // flags. p4est's 2:1 balance, which is global, still holds.
    triangulation.set_mesh_smoothing(
      Triangulation<dim>::limit_level_difference_at_vertices);
    flag_cells(triangulation,
               indicators,
               uniform_boundary_ids,
               "The adaptation during the run (Mesh refinement/Refinement "
               "fraction = "
                 + to_text(refine_fraction)
                 + ", Maximum level = " + std::to_string(maximum_level) + ")",
               true);
    bool flagged = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned()
          && (cell->refine_flag_set() || cell->coarsen_flag_set()))
        flagged = true;
    return Utilities::MPI::logical_or(flagged,
                                      triangulation.get_communicator());
  }



  template <int dim>
  void
  MeshRefinement<dim>::keep_within_budget(
    parallel::distributed::Triangulation<dim> &triangulation,
    const Vector<float>                       &indicators) const
  {
    // The cells the flags would make: each refined cell becomes 2^dim, each
    // coarsened family one. Within the budget the flags stand; else deal.II
    // flags the same fractions of the cells by their indicators, and
    // lowers the refined fraction until the mesh fits.
    double n_refined = 0, n_coarsened = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          n_refined += cell->refine_flag_set() ? 1 : 0;
          n_coarsened += cell->coarsen_flag_set() ? 1 : 0;
        }
    const MPI_Comm communicator = triangulation.get_communicator();
    n_refined                   = Utilities::MPI::sum(n_refined, communicator);
    n_coarsened            = Utilities::MPI::sum(n_coarsened, communicator);
    const double per_level = std::pow(2., dim);
    const double n_cells   = triangulation.n_global_active_cells();
    if (n_cells + (per_level - 1) * n_refined
          - (1 - 1 / per_level) * n_coarsened
        <= maximum_cells)
      return;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->clear_refine_flag();
          cell->clear_coarsen_flag();
        }
    parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
      triangulation,
      indicators,
      n_refined / n_cells,
      n_coarsened / n_cells,
      maximum_cells);
    clear_flags_beyond_levels(triangulation);
  }



  template <int dim>
  std::string
  MeshRefinement<dim>::run_description() const
  {
    if (!during_run)
      return "";
    return "every " + std::to_string(every_steps) + " steps, "
           + to_text(refine_fraction)
           + (fixed_fraction ? " of the indicator" : " of the cells")
           + " refined, " + to_text(coarsen_fraction) + " coarsened, levels "
           + std::to_string(minimum_level) + " to "
           + std::to_string(maximum_level)
           + (maximum_cells > 0 ?
                ", at most " + std::to_string(maximum_cells) + " cells" :
                std::string());
  }



  namespace
  {
    // Indicators closer than this (relative) count as equal: a run on
    // another number of ranks computes them with other round-off.
    constexpr double tie = 1e-6;

    // The number of the first of the @p sorted values (decreasing for
    // refinement, increasing for coarsening; none negative) that carry
    // @p fraction of their sum (by_sum) or of their number; the count grows
    // over values within tie of the last one taken, so that equal
    // indicators share their fate.
    std::size_t
    count_from_top(const std::vector<float> &sorted,
                   const double              fraction,
                   const bool                by_sum)
    {
      if (fraction <= 0 || sorted.empty())
        return 0;
      std::size_t m = 0;
      if (by_sum)
        {
          double total = 0, sum = 0;
          for (const float v : sorted)
            total += v;
          while (m < sorted.size() && sum < fraction * total)
            sum += sorted[m++];
        }
      else
        m = std::min<std::size_t>(sorted.size(),
                                  std::lround(fraction * sorted.size()));
      while (m > 0 && m < sorted.size()
             && std::abs(sorted[m] - sorted[m - 1])
                  <= tie * std::abs(sorted[m - 1]))
        ++m;
      return m;
    }
  } // namespace



  template <int dim>
  void
  MeshRefinement<dim>::flag_by_sorted_indicators(
    parallel::TriangulationBase<dim> &triangulation,
    const Vector<float>              &indicators) const
  {
    // Every rank sorts all ranks' indicators, and so finds the same
    // thresholds: the largest ones carrying Refinement fraction are refined,
    // the smallest ones carrying Coarsening fraction coarsened; with a cell
    // budget, only as many refined as keep the mesh within it.
    std::vector<float> own;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        own.push_back(indicators[cell->active_cell_index()]);
    std::vector<float> sorted;
    for (const auto &part :
         Utilities::MPI::all_gather(triangulation.get_communicator(), own))
      sorted.insert(sorted.end(), part.begin(), part.end());
    std::sort(sorted.begin(), sorted.end(), std::greater<float>());
    const std::vector<float> ascending(sorted.rbegin(), sorted.rend());
    std::size_t              n_refine
      = count_from_top(sorted, refine_fraction, fixed_fraction);
    const std::size_t n_coarsen
      = std::min(sorted.size() - n_refine,
                 count_from_top(ascending, coarsen_fraction, fixed_fraction));
    const double per_level = std::pow(2., dim);
    while (maximum_cells > 0 && n_refine > 0
           && sorted.size() + (per_level - 1) * n_refine
                  - (1 - 1 / per_level) * n_coarsen
                > maximum_cells)
      --n_refine;
    const double refine_above = n_refine > 0 ?
                                  sorted[n_refine - 1] * (1 - tie) :
                                  std::numeric_limits<double>::infinity();
    const double coarsen_below
      = n_coarsen > 0 ? ascending[n_coarsen - 1] * (1 + tie) : -1.;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double eta = indicators[cell->active_cell_index()];
          if (eta >= refine_above)
            cell->set_refine_flag();
          else if (eta <= coarsen_below)
            cell->set_coarsen_flag();
        }
    clear_flags_beyond_levels(triangulation);
  }



  template class MeshRefinement<2>;
  template class MeshRefinement<3>;
} // namespace VPContact
