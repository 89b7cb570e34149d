// The section "Mesh refinement" and the refinement of the mesh between
// cycles and during a run.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/mesh_checks.h>
#include <vpcontact/refinement/mesh_refinement.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>

namespace VPContact
{
  template <int dim>
  void
  MeshRefinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry(
        "Number of cycles",
        "1",
        Patterns::Integer(1, 30),
        "Runs over the whole time interval, each on the mesh refined from "
        "the previous one and from t = 0. With more than one, each cycle "
        "writes to Output/Directory/cycle-N and the program writes the "
        "convergence table convergence.csv in Output/Directory.");
      prm.declare_entry("Strategy",
                        "uniform",
                        Patterns::Selection("uniform|adaptive"),
                        "'uniform': every cell is refined between cycles (h "
                        "halves). 'adaptive': cells are refined and "
                        "coarsened by the space part of the error estimate "
                        "of the previous cycle (section Error estimate; the "
                        "largest over the time steps of each cell's "
                        "indicator; doc/convergence.md).");
      prm.declare_entry("Refinement criterion",
                        "fixed fraction",
                        Patterns::Selection("fixed fraction|fixed number"),
                        "Adaptive only. 'fixed fraction': refine the cells "
                        "that carry 'Refinement fraction' of the summed "
                        "indicator (coarsen those with 'Coarsening fraction' "
                        "of it). 'fixed number': refine that fraction of the "
                        "cells (coarsen that fraction), by largest indicator.");
      prm.declare_entry("Refinement fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "Adaptive only: see Refinement criterion.");
      prm.declare_entry("Coarsening fraction",
                        "0",
                        Patterns::Double(0, 1),
                        "Adaptive only: see Refinement criterion. Cells are "
                        "never coarsened below the coarse mesh.");
      prm.declare_entry("Maximum level",
                        "10",
                        Patterns::Integer(0, 20),
                        "No cell is refined beyond this many levels above "
                        "the coarse mesh (the box of Geometry/Subdivisions, "
                        "or the mesh file's cells), Geometry/Global "
                        "refinements included.");
    }
    prm.leave_subsection();
    declare_time_step_entries(prm);
    declare_run_entries(prm);
  }



  template <int dim>
  void
  MeshRefinement<dim>::declare_time_step_entries(ParameterHandler &prm)
  {
    // How each cycle's time step follows from the mesh or the estimate.
    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry(
        "Refine time step with mesh",
        "true",
        Patterns::Bool(),
        "Halve Time/Time step whenever the mesh size halves, so that k stays "
        "proportional to h (the error is O(h + k)). The mesh size of a cycle "
        "is the equivalent h = (|Omega| / cells)^(1/dim); k is halved the "
        "nearest whole number of times, which keeps the time grids of all "
        "cycles nested.");
      prm.declare_entry(
        "Time step from error estimate",
        "false",
        Patterns::Bool(),
        "Adaptive only; replaces 'Refine time step with mesh'. Choose each "
        "cycle's time step from the error estimate of the previous one: k "
        "is halved the whole number of times (never fewer than 0) that "
        "brings the time part, proportional to k, nearest to 1/dim of the "
        "space part expected on the new mesh (the previous one scaled by "
        "the ratio of equivalent mesh sizes): the cheapest split of the "
        "error when the run's cost is cells/k and the space part is first "
        "order in h (doc/convergence.md).");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  MeshRefinement<dim>::parse_parameters(ParameterHandler  &prm,
                                        const unsigned int base)
  {
    base_level = base;
    prm.enter_subsection("Mesh refinement");
    cycles           = prm.get_integer("Number of cycles");
    refinement       = (prm.get("Strategy") == "adaptive" ? Strategy::adaptive :
                                                            Strategy::uniform);
    fixed_fraction   = (prm.get("Refinement criterion") == "fixed fraction");
    refine_fraction  = prm.get_double("Refinement fraction");
    coarsen_fraction = prm.get_double("Coarsening fraction");
    maximum_level    = prm.get_integer("Maximum level");
    minimum_level    = prm.get_integer("Minimum level");
    maximum_cells    = prm.get_integer("Maximum cells");
    during_run       = prm.get_bool("Adapt during run");
    every_steps      = prm.get_integer("Adapt every");
    n_initial        = prm.get_integer("Initial adaptations");
    refine_time_step = prm.get_bool("Refine time step with mesh");
    step_from_estimate = prm.get_bool("Time step from error estimate");
    prm.leave_subsection();

    VPContactCheckParameter(!step_from_estimate
                              || refinement == Strategy::adaptive,
                            "Mesh refinement/Time step from error estimate",
                            std::string("true"),
                            "it applies to adaptive cycles only (Strategy = "
                            "uniform refines k with h). Set it to false or "
                            "use Strategy = adaptive.");

    VPContactCheckParameter(
      refine_fraction + coarsen_fraction <= 1.,
      "Mesh refinement/Coarsening fraction",
      coarsen_fraction,
      "the refinement and coarsening fractions add up to more than 1 "
      "(Refinement fraction = "
        + to_text(refine_fraction) + "). Lower one of them.");
    VPContactCheckParameter(!during_run || cycles == 1,
                            "Mesh refinement/Adapt during run",
                            std::string("true"),
                            "a run that adapts its mesh is one run; "
                            "refinement cycles (Number of cycles = "
                              + std::to_string(cycles)
                              + ") repeat runs on meshes refined between "
                                "them. Set Number of cycles = 1, or Adapt "
                                "during run = false.");
    VPContactCheckParameter(minimum_level <= maximum_level,
                            "Mesh refinement/Minimum level",
                            minimum_level,
                            "it is above Maximum level = "
                              + std::to_string(maximum_level) + ".");
    VPContactCheckParameter((refinement == Strategy::uniform && !during_run)
                              || refine_fraction > 0.
                              || (cycles == 1 && !during_run),
                            "Mesh refinement/Refinement fraction",
                            refine_fraction,
                            "adaptive cycles with nothing to refine repeat "
                            "the same run. Give a fraction in (0, 1].");
  }



  template <int dim>
  double
  MeshRefinement<dim>::largest_growth(
    const unsigned int global_refinements) const
  {
    if (cycles == 1)
      return 1;
    const double per_level = std::pow(2., dim);
    if (refinement == Strategy::adaptive)
      {
        VPContactCheckParameter(global_refinements < maximum_level,
                                "Mesh refinement/Maximum level",
                                maximum_level,
                                "Geometry/Global refinements = "
                                  + std::to_string(global_refinements)
                                  + " already reaches it: the adaptive cycles "
                                    "could refine nothing and would repeat "
                                    "the same run. Raise it.");
        // No cell goes beyond Maximum level; 'fixed number' refines that
        // fraction of the cells in each cycle, 'fixed fraction' = 1 all of
        // them. Below 1, the cells that carry a fraction of the estimate
        // are not known before: refine() checks each cycle's mesh.
        const double deepest
          = std::pow(per_level,
                     std::min<double>(cycles - 1,
                                      maximum_level - global_refinements));
        if (!fixed_fraction)
          return std::min(std::pow(1 + (per_level - 1) * refine_fraction,
                                   cycles - 1.),
                          deepest);
        return refine_fraction >= 1 ? deepest : 1;
      }
    const unsigned int finest = global_refinements + cycles - 1;
    VPContactCheckParameter(finest <= maximum_level,
                            "Mesh refinement/Number of cycles",
                            cycles,
                            "with Geometry/Global refinements = "
                              + std::to_string(global_refinements)
                              + " the last uniform cycle would refine the "
                                "mesh to level "
                              + std::to_string(finest)
                              + ", beyond Mesh refinement/Maximum level = "
                              + std::to_string(maximum_level)
                              + ". Use fewer cycles or raise the level.");
    return std::pow(per_level, cycles - 1.);
  }



  template <int dim>
  std::string
  MeshRefinement<dim>::size_entries() const
  {
    if (cycles == 1)
      return "";
    return ", Mesh refinement/Number of cycles = " + std::to_string(cycles)
           + (refinement == Strategy::uniform ?
                std::string() :
                " with Strategy = adaptive, Refinement criterion = "
                  + std::string(fixed_fraction ? "fixed fraction" :
                                                 "fixed number")
                  + ", Refinement fraction = " + to_text(refine_fraction)
                  + " and Maximum level = " + std::to_string(maximum_level));
  }



  template <int dim>
  unsigned int
  MeshRefinement<dim>::n_cycles() const
  {
    return cycles;
  }



  template <int dim>
  bool
  MeshRefinement<dim>::needs_indicators() const
  {
    return (cycles > 1 && refinement == Strategy::adaptive) || during_run;
  }



  template <int dim>
  unsigned int
  MeshRefinement<dim>::time_step_halvings(const double h_first,
                                          const double h) const
  {
    if (!refine_time_step || h >= h_first)
      return 0;
    return static_cast<unsigned int>(std::lround(std::log2(h_first / h)));
  }



  template <int dim>
  bool
  MeshRefinement<dim>::time_step_from_estimate() const
  {
    return step_from_estimate;
  }



  template <int dim>
  void
  MeshRefinement<dim>::refine(
    parallel::TriangulationBase<dim>   &triangulation,
    const Vector<float>                &indicators,
    const std::set<types::boundary_id> &uniform_boundary_ids) const
  {
    if (refinement == Strategy::uniform)
      {
        AssertThrow(triangulation.n_global_levels()
                      <= base_level + maximum_level,
                    ExcMessage("Mesh refinement/Maximum level = "
                               + std::to_string(maximum_level)
                               + " is reached: the next uniform cycle would "
                                 "go beyond it. Raise it or use fewer "
                                 "Number of cycles."));
        triangulation.refine_global(1);
        return;
      }
    flag_cells(triangulation,
               indicators,
               uniform_boundary_ids,
               "The next adaptive cycle (" + size_entries().substr(2) + ")");
    triangulation.execute_coarsening_and_refinement();
  }



  template <int dim>
  void
  MeshRefinement<dim>::flag_cells(
    parallel::TriangulationBase<dim>   &triangulation,
    const Vector<float>                &indicators,
    const std::set<types::boundary_id> &uniform_boundary_ids,
    const std::string                  &what,
    const bool                          same_on_any_ranks) const
  {
    if (same_on_any_ranks)
      flag_by_sorted_indicators(triangulation, indicators);
    else
      flag_adaptively(triangulation, indicators);

    // The contact cells move together: if one of them is to be refined, all
    // are, and none is coarsened. Mesh smoothing (one level difference at
    // vertices) may add flags next to them, so repeat until nothing changes.
    const MPI_Comm communicator = triangulation.get_communicator();
    for (bool changed = true; changed;)
      {
        triangulation.prepare_coarsening_and_refinement();
        bool any_refined = false, all_refined = true;
        std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && cell->at_boundary())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary()
                  && uniform_boundary_ids.count(face->boundary_id()) > 0)
                {
                  cells.push_back(cell);
                  cell->clear_coarsen_flag();
                  any_refined = any_refined || cell->refine_flag_set();
                  all_refined = all_refined && cell->refine_flag_set();
                  break;
                }
        any_refined = Utilities::MPI::logical_or(any_refined, communicator);
        all_refined = !Utilities::MPI::logical_or(!all_refined, communicator);
        changed     = any_refined && !all_refined;
        if (changed)
          for (const auto &cell : cells)
            cell->set_refine_flag();
      }
    check_memory_of_next_mesh(triangulation, what);
  }



  template <int dim>
  void
  MeshRefinement<dim>::check_memory_of_next_mesh(
    const parallel::TriangulationBase<dim> &triangulation,
    const std::string                      &what) const
  {
    // Each cell flagged for refinement becomes 2^dim cells; coarsening
    // (which may not happen) is not counted.
    double flagged = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->refine_flag_set())
        ++flagged;
    flagged = Utilities::MPI::sum(flagged, triangulation.get_communicator());
    check_mesh_memory(dim,
                      triangulation.n_global_active_cells()
                        + (std::pow(2., dim) - 1) * flagged,
                      triangulation.n_cells(0),
                      false,
                      what,
                      triangulation.get_communicator());
  }



  template <int dim>
  void
  MeshRefinement<dim>::flag_adaptively(
    parallel::TriangulationBase<dim> &triangulation,
    const Vector<float>              &indicators) const
  {
    // The simulator refuses adaptive cycles on simplex meshes before the
    // first step; this is the last line of defence.
    auto *const distributed
      = dynamic_cast<parallel::distributed::Triangulation<dim> *>(
        &triangulation);
    AssertThrow(distributed != nullptr,
                ExcMessage("Mesh refinement/Strategy = adaptive needs a mesh "
                           "of quadrilaterals (hexahedra)."));
    if (fixed_fraction)
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_fraction(
        *distributed,
        indicators,
        refine_fraction,
        coarsen_fraction);
    else
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        *distributed,
        indicators,
        refine_fraction,
        coarsen_fraction);
    clear_flags_beyond_levels(triangulation);
    if (maximum_cells > 0)
      keep_within_budget(*distributed, indicators);
  }



  template <int dim>
  void
  MeshRefinement<dim>::clear_flags_beyond_levels(
    parallel::TriangulationBase<dim> &triangulation) const
  {
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->level() >= static_cast<int>(base_level + maximum_level))
            cell->clear_refine_flag();
          if (cell->level() <= static_cast<int>(base_level + minimum_level))
            cell->clear_coarsen_flag();
        }
  }



  template <int dim>
  std::string
  MeshRefinement<dim>::description() const
  {
    if (cycles == 1)
      return "one run (no refinement cycles)";
    std::string text = std::to_string(cycles) + " cycles, ";
    if (refinement == Strategy::uniform)
      text += "uniform refinement";
    else
      text += "adaptive refinement (" + to_text(refine_fraction)
              + (fixed_fraction ? " of the indicator" : " of the cells")
              + " refined, " + to_text(coarsen_fraction) + " coarsened)";
    return text
           + (step_from_estimate ? ", k from the error estimate" :
              refine_time_step   ? ", k proportional to h" :
                                   ", k fixed");
  }



  template <int dim>
  double
  equivalent_mesh_size(const parallel::TriangulationBase<dim> &tria)
  {
    double volume = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        volume += cell->measure();
    volume = Utilities::MPI::sum(volume, tria.get_communicator());
    return std::pow(volume / tria.n_global_active_cells(), 1. / dim);
  }



  template class MeshRefinement<2>;
  template class MeshRefinement<3>;
  template double
  equivalent_mesh_size(const parallel::TriangulationBase<2> &);
  template double
  equivalent_mesh_size(const parallel::TriangulationBase<3> &);
} // namespace VPContact
