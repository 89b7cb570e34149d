// renumber_in_cell_order(): the degrees of freedom of each block in a given
// order of the cells.
#include <vpcontact/fe/dof_order.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/fe/fe.h>

#include <algorithm>
#include <utility>

namespace VPContact
{
  template <int dim>
  void
  renumber_in_cell_order(
    DoFHandler<dim>                                            &dof_handler,
    const std::vector<unsigned int>                            &block_component,
    const std::function<std::uint64_t(
      const typename DoFHandler<dim>::active_cell_iterator &)> &key)
  {
    using cell_iterator = typename DoFHandler<dim>::active_cell_iterator;
    const IndexSet            owned = dof_handler.locally_owned_dofs();
    const FiniteElement<dim> &fe    = dof_handler.get_fe();
    const unsigned int        n_blocks
      = *std::max_element(block_component.begin(), block_component.end()) + 1;

    // The owned cells by key, and the block of each owned degree of
    // freedom.
    constexpr unsigned int    unset = numbers::invalid_unsigned_int;
    std::vector<unsigned int> block_of(owned.n_elements(), unset);
    std::vector<std::pair<std::uint64_t, cell_iterator>> cells;
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cells.emplace_back(key(cell), cell);
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            if (owned.is_element(indices[i]))
              block_of[owned.index_within_set(indices[i])]
                = block_component[fe.system_to_component_index(i).first];
        }
    std::stable_sort(cells.begin(),
                     cells.end(),
                     [](const auto &a, const auto &b) {
                       return a.first < b.first;
                     });

    // Each block's owned indices, ascending: the ones it hands out in the
    // new order.
    std::vector<std::vector<types::global_dof_index>> indices_of_block(
      n_blocks);
    {
      unsigned int position = 0;
      for (const auto index : owned)
        {
          AssertThrow(block_of[position] != unset, ExcInternalError());
          indices_of_block[block_of[position++]].push_back(index);
        }
    }
    std::vector<std::size_t>             next(n_blocks, 0);
    std::vector<types::global_dof_index> new_numbers(
      owned.n_elements(),
      numbers::invalid_dof_index);
    for (const auto &[cell_key, cell] : cells)
      {
        (void)cell_key;
        cell->get_dof_indices(indices);
        for (const auto index : indices)
          if (owned.is_element(index))
            {
              const unsigned int p = owned.index_within_set(index);
              if (new_numbers[p] == numbers::invalid_dof_index)
                new_numbers[p]
                  = indices_of_block[block_of[p]][next[block_of[p]]++];
            }
      }
    dof_handler.renumber_dofs(new_numbers);
  }



  template void
  renumber_in_cell_order<2>(
    DoFHandler<2> &,
    const std::vector<unsigned int> &,
    const std::function<
      std::uint64_t(const typename DoFHandler<2>::active_cell_iterator &)> &);
  template void
  renumber_in_cell_order<3>(
    DoFHandler<3> &,
    const std::vector<unsigned int> &,
    const std::function<
      std::uint64_t(const typename DoFHandler<3>::active_cell_iterator &)> &);
} // namespace VPContact
