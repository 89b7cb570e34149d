// The simulator's mesh and its degrees of freedom, numbered by blocks.
#include <vpcontact/fe/dof_order.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/problem_data/rigid_motions.h>
#include <vpcontact/simulator/simulator.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <algorithm>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::make_mesh()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    if (checkpointing.resume())
      load_checkpoint_mesh();
    else
      geometry.create_mesh(*mesh);
    // Tresca friction, where the scene has it, joins the physics objects.
    if (Physics<dim> *const friction
        = displacement_problem.setup_contact(geometry.mesh_source()))
      physics.push_back(friction);
    collect_step_reports();
  }



  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    number_dofs();
    monitor_points.setup(dof_handler);
    displacement_problem.setup_dofs();
  }



  template <int dim>
  void
  Simulator<dim>::number_dofs()
  {
    dof_handler.distribute_dofs(discretization.finite_element());
    // Numbered by blocks, as in step-32 and step-55: all displacement
    // degrees of freedom first, node by node, then all damage ones. On each
    // rank the owned ones of each block are then a contiguous range, and in
    // the local entries of a vector on all of them the displacement comes
    // first: the displacement system is the block [0, n_u) alone, and the
    // damage system the block [n_u, n).
    std::vector<unsigned int> block_component(
      discretization.finite_element().n_components(),
      0);
    if (discretization.finite_element().n_components() > dim)
      block_component[dim] = 1;
    DoFRenumbering::component_wise(dof_handler, block_component);
    // On the forest of a box, in the order of the box's rows rather than of
    // the forest's Morton curve (see Geometry::box_cell_index()).
    if (geometry.base_level() > 0)
      renumber_in_cell_order<dim>(
        dof_handler,
        block_component,
        [this](const typename DoFHandler<dim>::active_cell_iterator &cell) {
          return geometry.box_cell_index(cell->center());
        });
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    output_layout.reinit(locally_owned_dofs, mpi_communicator);
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
