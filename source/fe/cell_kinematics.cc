// CellKinematics: the shape gradients, points and vector positions of every
// locally owned cell, computed once per mesh, and the strains, damage and
// stress work evaluated from them.
#include <vpcontact/fe/cell_kinematics.h>
#include <vpcontact/fe/cell_translation.h>
#include <vpcontact/fe/fixed_size_cell_kernels.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <array>
#include <cstring>
#include <string_view>
#include <unordered_map>

namespace VPContact
{
  namespace
  {
    // Throw unless every component of @p fe is the same scalar element (Q1),
    // with dim or dim + 1 components and at most @p max_nodes shape
    // functions each: then the displacement's and the damage's nodes
    // coincide, and one set of scalar gradients serves all of them.
    template <int dim>
    void
    check_same_scalar_elements(const FiniteElement<dim> &fe,
                               const unsigned int        max_nodes)
    {
      const FiniteElement<dim> &scalar = fe.base_element(0);
      bool same_scalar = scalar.n_components() == 1 && fe.n_components() >= dim;
      for (unsigned int b = 0; b < fe.n_base_elements(); ++b)
        same_scalar &= fe.base_element(b).get_name() == scalar.get_name();
      AssertThrow(same_scalar,
                  ExcMessage("CellKinematics expects dim or dim + 1 copies of "
                             "one scalar element."));
      AssertThrow(fe.base_element(0).n_dofs_per_cell() <= max_nodes,
                  ExcMessage("CellKinematics: too many shape functions per "
                             "component."));
    }

    // The values of the shape functions of @p scalar at the points of
    // @p quadrature, the same on every cell: N_a(x_q) at q * n_nodes + a.
    template <int dim>
    std::vector<double>
    scalar_shape_values(const FiniteElement<dim> &scalar,
                        const Quadrature<dim>    &quadrature)
    {
      const unsigned int  n_nodes = scalar.n_dofs_per_cell();
      std::vector<double> values(quadrature.size() * n_nodes);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        for (unsigned int a = 0; a < n_nodes; ++a)
          values[q * n_nodes + a] = scalar.shape_value(a, quadrature.point(q));
      return values;
    }

    // The position of the entry of degree of freedom @p dof in the local
    // storage of a vector of @p layout. A locally owned cell's degrees of
    // freedom are all there.
    unsigned int
    local_position(const Epetra_BlockMap        &layout,
                   const types::global_dof_index dof)
    {
      const int position
        = layout.LID(static_cast<TrilinosWrappers::types::int_type>(dof));
      AssertThrow(position >= 0,
                  ExcMessage("CellKinematics: a degree of freedom of "
                             "a locally owned cell is not in the "
                             "ghosted layout."));
      return position;
    }

    // The shape gradients of a cell depend only on its shape: the cells
    // that are translates of one another (every cell of a box, the cells of
    // one size of a refined box) have the same gradients. A cell that is
    // the last computed one moved (is_translate()) takes that cell's block;
    // FEValues reuses a translate's values only where deal.II runs one
    // thread, and computed anew at another place they can differ in the
    // last bits. Each distinct block of gradients is stored once, and a
    // cell keeps the index of its own: in 3D this saves 1.5 kB a cell on
    // such meshes (400 MB at 64^3 cells), and the passes over the cells
    // read one block from the cache instead of a block per cell from
    // memory. The other blocks are found by a hash of their bytes and
    // compared in full, so that a cell takes another cell's gradients only
    // where they are the same bits.
    template <int dim>
    class GradientBlocks
    {
    public:
      GradientBlocks(const unsigned int           block_size,
                     std::vector<Tensor<1, dim>> &storage)
        : block_size(block_size)
        , storage(storage)
      {}

      unsigned int
      index_of(const std::vector<Tensor<1, dim>> &block)
      {
        const std::string_view bytes(reinterpret_cast<const char *>(
                                       block.data()),
                                     block.size() * sizeof(Tensor<1, dim>));
        auto &candidates = by_hash[std::hash<std::string_view>()(bytes)];
        for (const unsigned int index : candidates)
          if (std::memcmp(&storage[index * block_size],
                          block.data(),
                          bytes.size())
              == 0)
            return index;
        const unsigned int index = storage.size() / block_size;
        storage.insert(storage.end(), block.begin(), block.end());
        candidates.push_back(index);
        return index;
      }

    private:
      const unsigned int                                         block_size;
      std::vector<Tensor<1, dim>>                               &storage;
      std::unordered_map<std::size_t, std::vector<unsigned int>> by_hash;
    };
  } // namespace



  template <int dim>
  void
  CellKinematics<dim>::reinit(const DoFHandler<dim> &dof_handler,
                              const Quadrature<dim> &quadrature,
                              const LA::MPI::Vector &ghosted)
  {
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    check_same_scalar_elements(fe, max_nodes);
    scalar        = fe.base_element(0).clone();
    n_q_points    = quadrature.size();
    n_nodes       = scalar->n_dofs_per_cell();
    dofs_per_cell = fe.n_dofs_per_cell();
    n_components  = fe.n_components();
    node_of.resize(dofs_per_cell);
    component_of.resize(dofs_per_cell);
    node_major = true;
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      {
        component_of[i] = fe.system_to_component_index(i).first;
        node_of[i]      = fe.system_to_component_index(i).second;
        node_major &= (component_of[i] == i % n_components
                       && node_of[i] == i / n_components);
      }
    shape_values = scalar_shape_values(*scalar, quadrature);

    const unsigned int n_cells
      = dof_handler.get_triangulation().n_active_cells();
    gradients.clear();
    gradient_block.assign(n_cells, 0);
    points.assign(n_cells * n_q_points, Point<dim>());
    positions.assign(n_cells * dofs_per_cell, 0);
    layout = std::make_unique<Epetra_BlockMap>(ghosted.trilinos_vector().Map());
    equal_layouts.clear();
    store_cells(dof_handler, quadrature);
    collect_displacement_nodes(dof_handler);
  }



  template <int dim>
  void
  CellKinematics<dim>::store_cells(const DoFHandler<dim> &dof_handler,
                                   const Quadrature<dim> &quadrature)
  {
    // The scalar element on the cells of the triangulation: only the
    // geometry is asked for, so no DoFHandler of its own is needed.
    FEValues<dim>                        fe_values(get_default_linear_mapping(
                              dof_handler.get_triangulation()),
                            *scalar,
                            quadrature,
                            update_gradients | update_quadrature_points);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    GradientBlocks              blocks(n_q_points * n_nodes, gradients);
    std::vector<Tensor<1, dim>> block(n_q_points * n_nodes);
    cell_iterator               reference;
    bool                        has_reference = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int c = cell->active_cell_index();
          fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
          for (unsigned int q = 0; q < n_q_points; ++q)
            points[c * n_q_points + q] = fe_values.quadrature_point(q);
          if (has_reference && is_translate(cell, reference))
            gradient_block[c] = gradient_block[reference->active_cell_index()];
          else
            {
              for (unsigned int q = 0; q < n_q_points; ++q)
                for (unsigned int a = 0; a < n_nodes; ++a)
                  block[q * n_nodes + a] = fe_values.shape_grad(a, q);
              gradient_block[c] = blocks.index_of(block);
              reference         = cell;
              has_reference     = true;
            }
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            positions[c * dofs_per_cell + i]
              = local_position(*layout, dof_indices[i]);
        }
  }



  template <int dim>
  void
  CellKinematics<dim>::collect_displacement_nodes(
    const DoFHandler<dim> &dof_handler)
  {
    // A node is known by the position of its first component.
    std::vector<std::array<unsigned int, dim>> node_dofs(n_nodes);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      if (component_of[i] < dim)
        node_dofs[node_of[i]][component_of[i]] = i;
    std::vector<bool> reached(layout->NumMyElements(), false);
    node_positions.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int *cell_positions
            = &positions[cell->active_cell_index() * dofs_per_cell];
          for (unsigned int a = 0; a < n_nodes; ++a)
            if (!reached[cell_positions[node_dofs[a][0]]])
              {
                reached[cell_positions[node_dofs[a][0]]] = true;
                for (unsigned int d = 0; d < dim; ++d)
                  node_positions.push_back(cell_positions[node_dofs[a][d]]);
              }
        }
  }



  template <int dim>
  bool
  CellKinematics<dim>::has_damage() const
  {
    return dofs_per_cell > dim * n_nodes;
  }



  template <int dim>
  const double *
  CellKinematics<dim>::local_entries(const LA::MPI::Vector &vector) const
  {
    Assert(layout, ExcMessage("CellKinematics::reinit() was not called."));
    // A full comparison of two layouts walks every index; it is done once
    // per vector (per layout data, which a vector keeps until it is
    // reinitialized), and the layouts found equal are remembered.
    const Epetra_BlockMap &map = vector.trilinos_vector().Map();
    for (const auto &known : equal_layouts)
      if (known.DataPtr() == map.DataPtr())
        return vector.begin();
    AssertThrow(map.SameAs(*layout),
                ExcMessage("CellKinematics: the vector is not in the ghosted "
                           "layout of the current mesh."));
    equal_layouts.push_back(map);
    return vector.begin();
  }



  template <int dim>
  void
  CellKinematics<dim>::strains(
    const cell_iterator                 &cell,
    const double                        *entries,
    ArrayView<SymmetricTensor<2, dim>> &&strains) const
  {
    AssertDimension(strains.size(), n_q_points);
    const unsigned int  c    = cell->active_cell_index();
    const unsigned int *dofs = &positions[c * dofs_per_cell];
    if (node_major
        && FixedSizeCellKernels::with_fixed_sizes<dim>(
          n_nodes,
          n_components,
          [&](auto nodes, auto components) {
            FixedSizeCellKernels::strains<dim, nodes, components>(
              dofs,
              entries,
              cell_gradients(c),
              n_q_points,
              strains.data());
          }))
      return;
    for (unsigned int q = 0; q < n_q_points; ++q)
      {
        const Tensor<1, dim> *grad = cell_gradients(c) + q * n_nodes;
        // The displacement gradient sum_a u_a (x) grad N_a, then its
        // symmetric part.
        Tensor<2, dim> du;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          if (component_of[i] < dim)
            du[component_of[i]] += entries[dofs[i]] * grad[node_of[i]];
        strains[q] = symmetrize(du);
      }
  }



  template <int dim>
  void
  CellKinematics<dim>::damage(const cell_iterator &cell,
                              const double        *entries,
                              ArrayView<double>  &&damage) const
  {
    AssertDimension(damage.size(), n_q_points);
    Assert(has_damage(), ExcInternalError());
    const unsigned int *dofs
      = &positions[cell->active_cell_index() * dofs_per_cell];
    if (node_major
        && FixedSizeCellKernels::with_fixed_sizes<dim>(
          n_nodes,
          n_components,
          [&](auto nodes, auto components) {
            if constexpr (components == dim + 1)
              FixedSizeCellKernels::damage<dim, nodes, components>(
                dofs,
                entries,
                shape_values.data(),
                n_q_points,
                damage.data());
          }))
      return;
    for (unsigned int q = 0; q < n_q_points; ++q)
      {
        double value = 0;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          if (component_of[i] == dim)
            value += entries[dofs[i]] * shape_values[q * n_nodes + node_of[i]];
        damage[q] = value;
      }
  }



  template <int dim>
  void
  CellKinematics<dim>::damage_gradients(
    const cell_iterator        &cell,
    const double               *entries,
    ArrayView<Tensor<1, dim>> &&damage_gradients) const
  {
    AssertDimension(damage_gradients.size(), n_q_points);
    Assert(has_damage(), ExcInternalError());
    const unsigned int  c    = cell->active_cell_index();
    const unsigned int *dofs = &positions[c * dofs_per_cell];
    for (unsigned int q = 0; q < n_q_points; ++q)
      {
        const Tensor<1, dim> *grad = cell_gradients(c) + q * n_nodes;
        Tensor<1, dim>        value;
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          if (component_of[i] == dim)
            value += entries[dofs[i]] * grad[node_of[i]];
        damage_gradients[q] = value;
      }
  }



  template <int dim>
  void
  CellKinematics<dim>::nodal_values(const cell_iterator &cell,
                                    const double        *entries,
                                    const unsigned int   component,
                                    ArrayView<double>  &&values) const
  {
    AssertDimension(values.size(), n_nodes);
    AssertIndexRange(component, dofs_per_cell / n_nodes);
    const unsigned int *dofs
      = &positions[cell->active_cell_index() * dofs_per_cell];
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      if (component_of[i] == component)
        values[node_of[i]] = entries[dofs[i]];
  }



  template <int dim>
  void
  CellKinematics<dim>::subtract_stress_work(
    const cell_iterator                           &cell,
    const ArrayView<const SymmetricTensor<2, dim>> weighted_stress,
    Vector<double>                                &cell_vector) const
  {
    AssertDimension(weighted_stress.size(), n_q_points);
    AssertDimension(cell_vector.size(), dofs_per_cell);
    const unsigned int c = cell->active_cell_index();
    if (node_major
        && FixedSizeCellKernels::with_fixed_sizes<dim>(
          n_nodes,
          n_components,
          [&](auto nodes, auto components) {
            FixedSizeCellKernels::subtract_stress_work<dim, nodes, components>(
              cell_gradients(c),
              weighted_stress.data(),
              n_q_points,
              cell_vector.data());
          }))
      return;
    // tau : sym(e_c (x) grad N_a) = (tau grad N_a)_c for a symmetric tau:
    // one product per node and point, shared by the dim components.
    std::array<Tensor<1, dim>, max_nodes> traction;
    for (unsigned int q = 0; q < n_q_points; ++q)
      {
        const Tensor<1, dim> *grad = cell_gradients(c) + q * n_nodes;
        for (unsigned int a = 0; a < n_nodes; ++a)
          traction[a] = weighted_stress[q] * grad[a];
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          if (component_of[i] < dim)
            cell_vector(i) -= traction[node_of[i]][component_of[i]];
      }
  }



  template class CellKinematics<2>;
  template class CellKinematics<3>;
} // namespace VPContact
