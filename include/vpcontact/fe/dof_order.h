// Numbers the degrees of freedom of each block in a given order of the
// cells, as DoFRenumbering::component_wise numbers them in the mesh's own.
#ifndef vpcontact_dof_order_h
#define vpcontact_dof_order_h

#include <deal.II/dofs/dof_handler.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Renumber the locally owned degrees of freedom within each block of
   * @p block_component (DoFRenumbering::component_wise() must have
   * numbered them by these blocks): the owned cells are visited by
   * ascending @p key (cells of equal keys in the mesh's order), the degrees
   * of freedom of a cell in its local order, and each one met for the first
   * time takes the next of the rank's owned indices of its block. Each rank
   * keeps its owned indices, and each block its indices.
   *
   * The numbering is then the one component_wise() gives on a mesh whose
   * cells come in the order of @p key. Only for meshes of
   * parallel::distributed::Triangulation (DoFHandler::renumber_dofs() with
   * the new indices of the owned degrees of freedom).
   */
  template <int dim>
  void
  renumber_in_cell_order(
    DoFHandler<dim>                                            &dof_handler,
    const std::vector<unsigned int>                            &block_component,
    const std::function<std::uint64_t(
      const typename DoFHandler<dim>::active_cell_iterator &)> &key);
} // namespace VPContact

#endif
