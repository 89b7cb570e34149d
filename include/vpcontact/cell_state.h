// The displacement strain and the damage of a finite element vector at the
// quadrature points of one cell, read from the cell's nodal values once.
#ifndef vpcontact_cell_state_h
#define vpcontact_cell_state_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The symmetric gradient of the displacement (components 0 to dim-1) of
   * @p vector at the points of @p fe_values, reinitialized on @p cell, into
   * @p strains, and, if @p damage_values is given, the damage (component
   * dim) into it. @p local_values is scratch space of fe.n_dofs_per_cell()
   * entries.
   *
   * Why the nodal values are read once: the passes that call this visit
   * every cell in every step, a ghosted Trilinos vector costs an index
   * lookup per entry read, and get_function_values() and its siblings read
   * the cell's entries again for each call, into a fresh heap vector.
   */
  template <int dim, typename VectorType>
  void
  evaluate_cell_state(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const FEValues<dim>                                  &fe_values,
    const VectorType                                     &vector,
    std::vector<double>                                  &local_values,
    std::vector<SymmetricTensor<2, dim>>                 &strains,
    std::vector<double> *const damage_values = nullptr)
  {
    const FEValuesExtractors::Vector u(0);
    const FEValuesExtractors::Scalar zeta(dim);
    cell->get_dof_values(vector, local_values.begin(), local_values.end());
    fe_values[u].get_function_symmetric_gradients_from_local_dof_values(
      local_values,
      strains);
    if (damage_values != nullptr)
      fe_values[zeta].get_function_values_from_local_dof_values(local_values,
                                                                *damage_values);
  }
} // namespace VPContact

#endif
