// The unit square refined globally and then twice more in the quarter disc
// around its corner (1, 1), with a Q1 vector field on it: a distributed mesh
// with hanging nodes, shared by the unit tests of threaded assembly and of
// owned constraints.
#ifndef vpcontact_test_corner_refined_mesh_h
#define vpcontact_test_corner_refined_mesh_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

struct CornerRefinedMesh
{
  CornerRefinedMesh(const MPI_Comm comm, const unsigned int global_refinements)
    : triangulation(comm)
    , fe(dealii::FE_Q<2>(1), 2)
    , dof_handler(triangulation)
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
    dof_handler.distribute_dofs(fe);
    owned = dof_handler.locally_owned_dofs();
    dealii::DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
  }

  dealii::parallel::distributed::Triangulation<2> triangulation;
  const dealii::FESystem<2>                       fe;
  dealii::DoFHandler<2>                           dof_handler;
  dealii::IndexSet                                owned;
  dealii::IndexSet                                relevant;
};

#endif
