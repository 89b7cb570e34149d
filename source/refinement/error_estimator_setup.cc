// ErrorEstimator's work once per mesh: the recovery space and its
// constraints, the lumped mass, the chunks and colors of the cells for the
// threads, and the per-cell data.
#include <vpcontact/refinement/error_estimator.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>

namespace VPContact
{
  template <int dim>
  void
  ErrorEstimator<dim>::setup(const parallel::TriangulationBase<dim> &tria,
                             const std::vector<cell_iterator> &owned_cells,
                             const CellKinematics<dim>        &cell_kinematics,
                             StressHistory<dim>               &stress_history,
                             const ScalarNodeSpace<dim>       *nodes)
  {
    // A scalar Q1 (P1) space on the mesh, the damage block's where there is
    // one; its owned and ghost nodes hold the recovered fields, all
    // components of a node side by side (the tensor product of the node's
    // index with the components).
    triangulation = &tria;
    cells         = &owned_cells;
    kinematics    = &cell_kinematics;
    history       = &stress_history;
    with_damage   = cell_kinematics.has_damage();
    if (nodes)
      {
        space = *nodes;
        recovery_dofs.clear();
      }
    else
      make_own_space(tria);
    const IndexSet &owned    = space.owned;
    const IndexSet &relevant = space.relevant;

    constexpr unsigned int n_tensor
      = SymmetricTensor<2, dim>::n_independent_components;
    n_components = 2 * n_tensor + (with_damage ? dim : 0);
    n_nodes      = cell_kinematics.scalar_element().n_dofs_per_cell();
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
    recovered_layout = std::make_shared<Utilities::MPI::Partitioner>(
      owned.tensor_product(components),
      relevant.tensor_product(components),
      communicator);
    recovered.reinit(recovered_layout);
    std::vector<unsigned int> positions;
    std::vector<bool>         plain;
    setup_nodes_and_mass(positions, plain);
    setup_chunks(std::move(positions), plain);
    setup_hanging_nodes();
    setup_cell_data();
    indicators.reinit(tria.n_active_cells());
    step_indicators.reinit(tria.n_active_cells());
    largest_sum  = ErrorEstimate();
    largest_part = ErrorEstimate();
  }



  template <int dim>
  void
  ErrorEstimator<dim>::make_own_space(
    const parallel::TriangulationBase<dim> &tria)
  {
    // Without damage the FESystem has no scalar block: a DoFHandler of the
    // scalar element on the same mesh.
    recovery_fe = kinematics->scalar_element().clone();
    recovery_dofs.reinit(tria);
    recovery_dofs.distribute_dofs(*recovery_fe);
    space.owned = recovery_dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(recovery_dofs, space.relevant);
    own_constraints.clear();
    own_constraints.reinit(space.relevant);
    DoFTools::make_hanging_node_constraints(recovery_dofs, own_constraints);
    own_constraints.close();
    space.constraints = &own_constraints;
    space.cell_nodes  = [this](const cell_iterator                  &cell,
                              std::vector<types::global_dof_index> &dofs) {
      const cell_iterator scalar_cell(triangulation,
                                      cell->level(),
                                      cell->index(),
                                      &recovery_dofs);
      scalar_cell->get_dof_indices(dofs);
    };
  }



  template <int dim>
  void
  ErrorEstimator<dim>::setup_nodes_and_mass(
    std::vector<unsigned int> &positions,
    std::vector<bool>         &plain)
  {
    // The nodes of every owned cell, by global index and by position in the
    // local storage of the scalar layout (@p positions), whether a cell has
    // no constrained (hanging) node (@p plain), and the lumped mass
    // sum_K int_K phi_i (condensed onto the nodes that carry the values
    // where the mesh has hanging nodes).
    node_indices.resize(cells->size() * n_nodes);
    positions.resize(cells->size() * n_nodes);
    plain.assign(cells->size(), true);
    std::vector<types::global_dof_index> dofs(n_nodes);
    Vector<double>                       cell_mass(n_nodes);
    for (std::size_t i = 0; i < cells->size(); ++i)
      {
        space.cell_nodes((*cells)[i], dofs);
        const auto JxW = history->JxW((*cells)[i]);
        AssertThrow(JxW.size() == n_q, ExcInternalError());
        cell_mass = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int a = 0; a < n_nodes; ++a)
            cell_mass(a) += kinematics->shape_value(q, a) * JxW[q];
        space.constraints->distribute_local_to_global(cell_mass,
                                                      dofs,
                                                      lumped_mass);
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            node_indices[i * n_nodes + a] = dofs[a];
            positions[i * n_nodes + a]
              = lumped_mass.get_partitioner()->global_to_local(dofs[a]);
            plain[i] = plain[i] && !space.constraints->is_constrained(dofs[a]);
            Assert(recovered_layout->global_to_local(dofs[a] * n_components)
                     == positions[i * n_nodes + a] * n_components,
                   ExcInternalError());
          }
      }
    lumped_mass.compress(VectorOperation::add);
  }



  template <int dim>
  void
  ErrorEstimator<dim>::setup_chunks(std::vector<unsigned int> &&positions,
                                    const std::vector<bool>    &plain)
  {
    // The cells without hanging nodes add their moments to their nodes'
    // entries directly, chunk by chunk, color by color (see
    // ConflictFreeChunks): every node receives its sums in the same order
    // with any number of threads. A chunk size that does not depend on the
    // number of threads keeps the order, and so the bits, the same on any
    // machine; 256 cells give a 512^2 mesh a thousand chunks for the
    // threads.
    chunks.reinit(std::move(positions), n_nodes, plain, 256);
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
    for (const std::size_t i : chunks.other_cells())
      for (unsigned int a = 0; a < n_nodes; ++a)
        {
          const auto dof   = node_indices[i * n_nodes + a];
          const auto local = chunks.positions(i)[a];
          if (!space.constraints->is_constrained(dof) || listed[local])
            continue;
          listed[local] = true;
          hanging_nodes.push_back(local);
          for (const auto &entry :
               *space.constraints->get_constraint_entries(dof))
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
    // (h_K / pi)^2, which depends on the mesh only.
    damage_weights.resize(cells->size());
    for (std::size_t i = 0; i < cells->size(); ++i)
      {
        const double h_over_pi = (*cells)[i]->diameter() / numbers::PI;
        damage_weights[i]      = h_over_pi * h_over_pi;
      }
  }



  template class ErrorEstimator<2>;
  template class ErrorEstimator<3>;
} // namespace VPContact
