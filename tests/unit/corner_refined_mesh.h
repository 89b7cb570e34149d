// The unit square refined globally and then twice more in the quarter disc
// around its corner (1, 1): a distributed mesh with hanging nodes, shared by
// the unit tests of threaded assembly and of owned constraints.
#ifndef vpcontact_test_corner_refined_mesh_h
#define vpcontact_test_corner_refined_mesh_h

#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>

inline void
make_corner_refined_mesh(
  dealii::parallel::distributed::Triangulation<2> &triangulation,
  const unsigned int                               global_refinements)
{
  dealii::GridGenerator::hyper_cube(triangulation);
  triangulation.refine_global(global_refinements);
  for (unsigned int level = 0; level < 2; ++level)
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->center()[0] > 0.5
            && cell->center()[1] > 0.5 && cell->center().norm() < 0.9)
          cell->set_refine_flag();
      triangulation.execute_coarsening_and_refinement();
    }
}

#endif
