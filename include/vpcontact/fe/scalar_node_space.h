// A scalar Q1 (P1) space of nodes on the mesh, as a numbering with its
// index sets, hanging node constraints and the nodes of each cell: the one
// space that the damage and the error estimate's recovery share.
#ifndef vpcontact_scalar_node_space_h
#define vpcontact_scalar_node_space_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <functional>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * A scalar Q1 (P1) space of nodes on the mesh, in a numbering of its
   * own: its locally owned and relevant nodes, its hanging node
   * constraints, and the nodes of each locally owned cell in the order of
   * the scalar element's shape functions. In damage scenes the damage
   * block of the FESystem is such a space (DamageSystem), and the
   * estimator recovers its fields there instead of on a space of its own.
   */
  template <int dim>
  struct ScalarNodeSpace
  {
    IndexSet                         owned;
    IndexSet                         relevant;
    const AffineConstraints<double> *constraints = nullptr;
    std::function<void(const typename DoFHandler<dim>::active_cell_iterator &,
                       std::vector<types::global_dof_index> &)>
      cell_nodes;
  };
} // namespace VPContact

#endif
