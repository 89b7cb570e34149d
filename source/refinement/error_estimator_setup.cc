// ErrorEstimator's work once per mesh: the recovery space and its
// constraints, the lumped mass, the cells that share each node, and the
// per-cell data and buffers that the passes of every step reuse.
#include <vpcontact/refinement/error_estimator.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace VPContact
{
  template <int dim>
  void
  ErrorEstimator<dim>::setup(const parallel::TriangulationBase<dim> &tria,
                             const std::vector<cell_iterator> &owned_cells,
                             const CellKinematics<dim>        &cell_kinematics,
                             StressHistory<dim>               &stress_history)
  {
    // A scalar Q1 (P1) space on the mesh; its owned and ghost nodes hold the
    // recovered fields, all components of a node side by side (the tensor
    // product of the node's index with the components).
    triangulation = &tria;
    cells         = &owned_cells;
    kinematics    = &cell_kinematics;
    history       = &stress_history;
    with_damage   = cell_kinematics.has_damage();
    recovery_fe   = cell_kinematics.scalar_element().clone();
    recovery_dofs.reinit(tria);
    recovery_dofs.distribute_dofs(*recovery_fe);
    const IndexSet owned = recovery_dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(recovery_dofs, relevant);
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(recovery_dofs, constraints);
    constraints.close();

    constexpr unsigned int n_tensor
      = SymmetricTensor<2, dim>::n_independent_components;
    n_components = 2 * n_tensor + (with_damage ? dim : 0);
    n_nodes      = recovery_fe->n_dofs_per_cell();
    n_q = owned_cells.empty() ? 0 : stress_history.JxW(owned_cells[0]).size();
    AssertThrow(n_q <= max_points && n_nodes <= max_nodes,
                ExcMessage("ErrorEstimator: more quadrature points or nodes "
                           "per cell than it is built for."));
    AssertThrow(owned_cells.size() * n_nodes
                  < std::numeric_limits<unsigned int>::max(),
                ExcMessage("ErrorEstimator: too many cells on one rank."));

    const MPI_Comm communicator = tria.get_communicator();
    const IndexSet components   = complete_index_set(n_components);
    lumped_mass.reinit(owned, relevant, communicator);
    recovered.reinit(owned.tensor_product(components),
                     relevant.tensor_product(components),
                     communicator);
    setup_nodes_and_mass();
    setup_gather();
    setup_hanging_nodes();
    setup_cell_data();
    indicators.reinit(tria.n_active_cells());
    largest_sum  = ErrorEstimate();
    largest_part = ErrorEstimate();
  }



  template <int dim>
  void
  ErrorEstimator<dim>::setup_nodes_and_mass()
  {
    // The nodes of every owned cell, by global index and by position in the
    // local storage of the scalar layout, and the lumped mass
    // sum_K int_K phi_i (condensed onto the nodes that carry the values
    // where the mesh has hanging nodes).
    node_indices.resize(cells->size() * n_nodes);
    node_locals.resize(cells->size() * n_nodes);
    has_constraints.assign(cells->size(), false);
    std::vector<types::global_dof_index> dofs(n_nodes);
    Vector<double>                       cell_mass(n_nodes);
    for (std::size_t i = 0; i < cells->size(); ++i)
      {
        const typename DoFHandler<dim>::active_cell_iterator cell(
          triangulation,
          (*cells)[i]->level(),
          (*cells)[i]->index(),
          &recovery_dofs);
        cell->get_dof_indices(dofs);
        const auto JxW = history->JxW((*cells)[i]);
        AssertThrow(JxW.size() == n_q, ExcInternalError());
        cell_mass = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int a = 0; a < n_nodes; ++a)
            cell_mass(a) += kinematics->shape_value(q, a) * JxW[q];
        constraints.distribute_local_to_global(cell_mass, dofs, lumped_mass);
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            node_indices[i * n_nodes + a] = dofs[a];
            node_locals[i * n_nodes + a]
              = lumped_mass.get_partitioner()->global_to_local(dofs[a]);
            has_constraints[i]
              = has_constraints[i] || constraints.is_constrained(dofs[a]);
            Assert(recovered.get_partitioner()->global_to_local(dofs[a]
                                                                * n_components)
                     == node_locals[i * n_nodes + a] * n_components,
                   ExcInternalError());
          }
      }
    lumped_mass.compress(VectorOperation::add);
  }



  template <int dim>
  void
  ErrorEstimator<dim>::setup_gather()
  {
    // For each local node (owned and ghost), the slots of the cells without
    // hanging nodes that share it, in the cells' order: the sums of the
    // projection then run over the nodes in the threads, and each node adds
    // its cells' moments in the order in which one thread going from cell
    // to cell would.
    const auto        &partitioner = *lumped_mass.get_partitioner();
    const unsigned int n_local
      = partitioner.locally_owned_size() + partitioner.n_ghost_indices();
    slot_start.assign(n_local + 1, 0);
    constrained_cells.clear();
    for (std::size_t i = 0; i < cells->size(); ++i)
      if (has_constraints[i])
        constrained_cells.push_back(i);
      else
        for (unsigned int a = 0; a < n_nodes; ++a)
          ++slot_start[node_locals[i * n_nodes + a] + 1];
    std::partial_sum(slot_start.begin(), slot_start.end(), slot_start.begin());
    slots.resize(slot_start.back());
    std::vector<unsigned int> next(slot_start.begin(), slot_start.end() - 1);
    for (std::size_t i = 0; i < cells->size(); ++i)
      if (!has_constraints[i])
        for (unsigned int a = 0; a < n_nodes; ++a)
          slots[next[node_locals[i * n_nodes + a]]++] = i * n_nodes + a;
  }



  template <int dim>
  void
  ErrorEstimator<dim>::setup_hanging_nodes()
  {
    // The constrained nodes of the owned cells, and the nodes and weights
    // they take their values from after the exchange: those lie on the
    // coarser neighbour of an owned cell, so they are locally relevant.
    const auto       &partitioner = *lumped_mass.get_partitioner();
    std::vector<bool> listed(partitioner.locally_owned_size()
                               + partitioner.n_ghost_indices(),
                             false);
    hanging_nodes.clear();
    hanging_start.assign(1, 0);
    hanging_parents.clear();
    for (const std::size_t i : constrained_cells)
      for (unsigned int a = 0; a < n_nodes; ++a)
        {
          const auto dof   = node_indices[i * n_nodes + a];
          const auto local = node_locals[i * n_nodes + a];
          if (!constraints.is_constrained(dof) || listed[local])
            continue;
          listed[local] = true;
          hanging_nodes.push_back(local);
          for (const auto &entry : *constraints.get_constraint_entries(dof))
            hanging_parents.emplace_back(partitioner.global_to_local(
                                           entry.first),
                                         entry.second);
          hanging_start.push_back(hanging_parents.size());
        }
  }



  template <int dim>
  void
  ErrorEstimator<dim>::setup_cell_data()
  {
    // (h_K / pi)^2, which depends on the mesh only, and the buffers of the
    // passes of every step, allocated here once rather than in every step.
    damage_weights.resize(cells->size());
    for (std::size_t i = 0; i < cells->size(); ++i)
      {
        const double h_over_pi = (*cells)[i]->diameter() / numbers::PI;
        damage_weights[i]      = h_over_pi * h_over_pi;
      }
    moments.assign(cells->size() * n_nodes * n_components, 0.);
    point_values.assign(cells->size() * n_q * n_components, 0.);
    norms.resize(cells->size());
  }



  template class ErrorEstimator<2>;
  template class ErrorEstimator<3>;
} // namespace VPContact
