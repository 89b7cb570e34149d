// The connected parts of a distributed mesh, found by union-find on each
// rank and a label exchange through the ghost layer.
#include <vpcontact/fe/mesh_parts.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>

namespace VPContact
{
  namespace
  {
    // The root of the tree of @p i, halving the path on the way.
    unsigned int
    find_root(std::vector<unsigned int> &parent, unsigned int i)
    {
      while (parent[i] != i)
        {
          parent[i] = parent[parent[i]];
          i         = parent[i];
        }
      return i;
    }

    // The root of the component of every locally relevant dof (by its index
    // in @p relevant) on this rank's owned and ghost cells: every cell joins
    // its nodes.
    template <int dim>
    std::vector<unsigned int>
    local_components(const DoFHandler<dim> &dof_handler,
                     const IndexSet        &relevant)
    {
      std::vector<unsigned int> parent(relevant.n_elements());
      std::iota(parent.begin(), parent.end(), 0u);
      std::vector<types::global_dof_index> dofs(
        dof_handler.get_fe().n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            const unsigned int first
              = find_root(parent, relevant.index_within_set(dofs[0]));
            for (const auto dof : dofs)
              parent[find_root(parent, relevant.index_within_set(dof))] = first;
          }
      for (unsigned int i = 0; i < parent.size(); ++i)
        parent[i] = find_root(parent, i);
      return parent;
    }

    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::string text = "(";
      for (unsigned int d = 0; d < dim; ++d)
        text += (d > 0 ? ", " : "") + to_text(p[d]);
      return text + ")";
    }
  } // namespace



  template <int dim>
  MeshParts<dim>::MeshParts(const DoFHandler<dim> &dof_handler)
  {
    label_components(dof_handler);
    measure_parts(dof_handler);
  }



  template <int dim>
  void
  MeshParts<dim>::label_components(const DoFHandler<dim> &dof_handler)
  {
    const MPI_Comm  communicator = dof_handler.get_communicator();
    const IndexSet &owned        = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    std::vector<types::global_dof_index> global;
    relevant.fill_index_vector(global);

    const std::vector<unsigned int> root
      = local_components(dof_handler, relevant);

    // A component that crosses ranks is seen in pieces; the smallest label
    // of each piece reaches the neighbouring ranks through the dofs they
    // share, one rank boundary per round. Labels are exact in a double.
    // (Trilinos vectors, as everywhere in the program: deal.II 9.4's own
    // distributed vector hangs on the two ranges of owned dofs of a scene
    // with damage.)
    LA::MPI::Vector label(owned, communicator);
    LA::MPI::Vector ghosted(owned, relevant, communicator);
    for (const auto dof : owned)
      label(dof) = static_cast<double>(dof);
    std::vector<double> smallest(global.size());
    for (;;)
      {
        ghosted = label;
        std::fill(smallest.begin(),
                  smallest.end(),
                  std::numeric_limits<double>::max());
        for (unsigned int i = 0; i < global.size(); ++i)
          smallest[root[i]]
            = std::min<double>(smallest[root[i]], ghosted(global[i]));
        unsigned int lowered = 0;
        for (unsigned int i = 0; i < global.size(); ++i)
          if (owned.is_element(global[i])
              && smallest[root[i]] < label(global[i]))
            {
              label(global[i]) = smallest[root[i]];
              ++lowered;
            }
        if (Utilities::MPI::sum(lowered, communicator) == 0)
          break;
      }
    labels.resize(global.size());
    for (unsigned int i = 0; i < global.size(); ++i)
      labels[i] = static_cast<types::global_dof_index>(smallest[root[i]]);

    std::set<types::global_dof_index> mine;
    for (const auto dof : owned)
      mine.insert(labels[relevant.index_within_set(dof)]);
    const std::set<types::global_dof_index> all
      = Utilities::MPI::compute_set_union(mine, communicator);
    part_labels.assign(all.begin(), all.end());
  }



  template <int dim>
  void
  MeshParts<dim>::measure_parts(const DoFHandler<dim> &dof_handler)
  {
    const MPI_Comm     communicator = dof_handler.get_communicator();
    const unsigned int n            = n_parts();
    cells.assign(n, 0);
    std::vector<double> lower(n * dim, std::numeric_limits<double>::max());
    std::vector<double> upper(n * dim, -std::numeric_limits<double>::max());
    // The boundary ids of each part as bits (ids 0..255, which is all the
    // boundary conditions can name), so that one bitwise-or gathers them.
    std::vector<unsigned int>            id_bits(n * 8, 0u);
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          const unsigned int part = part_of(dofs[0]);
          ++cells[part];
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[part * dim + d]
                  = std::min(lower[part * dim + d], cell->vertex(v)[d]);
                upper[part * dim + d]
                  = std::max(upper[part * dim + d], cell->vertex(v)[d]);
              }
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() < 256)
              id_bits[part * 8 + face->boundary_id() / 32]
                |= (1u << (face->boundary_id() % 32));
        }
    Utilities::MPI::sum(cells, communicator, cells);
    Utilities::MPI::min(lower, communicator, lower);
    Utilities::MPI::max(upper, communicator, upper);
    boxes.resize(n);
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int d = 0; d < dim; ++d)
        {
          boxes[p].first[d]  = lower[p * dim + d];
          boxes[p].second[d] = upper[p * dim + d];
        }
    MPI_Allreduce(MPI_IN_PLACE,
                  id_bits.data(),
                  id_bits.size(),
                  MPI_UNSIGNED,
                  MPI_BOR,
                  communicator);
    ids.assign(n, {});
    for (unsigned int p = 0; p < n; ++p)
      for (types::boundary_id id = 0; id < 256; ++id)
        if (id_bits[p * 8 + id / 32] & (1u << (id % 32)))
          ids[p].insert(id);
  }



  template <int dim>
  unsigned int
  MeshParts<dim>::n_parts() const
  {
    return part_labels.size();
  }



  template <int dim>
  unsigned int
  MeshParts<dim>::part_of(const types::global_dof_index dof) const
  {
    const types::global_dof_index label
      = labels[relevant.index_within_set(dof)];
    return std::lower_bound(part_labels.begin(), part_labels.end(), label)
           - part_labels.begin();
  }



  template <int dim>
  types::global_cell_index
  MeshParts<dim>::n_cells(const unsigned int part) const
  {
    return cells[part];
  }



  template <int dim>
  std::pair<Point<dim>, Point<dim>>
  MeshParts<dim>::bounding_box(const unsigned int part) const
  {
    return boxes[part];
  }



  template <int dim>
  const std::set<types::boundary_id> &
  MeshParts<dim>::boundary_ids(const unsigned int part) const
  {
    return ids[part];
  }



  template <int dim>
  std::string
  MeshParts<dim>::description(const unsigned int part) const
  {
    std::string id_text;
    for (const auto id : ids[part])
      id_text += (id_text.empty() ? "" : ", ") + std::to_string(id);
    return "the part of " + std::to_string(cells[part]) + " cells between "
           + point_text(boxes[part].first) + " and "
           + point_text(boxes[part].second) + " (boundary ids "
           + (id_text.empty() ? std::string("none") : id_text) + ")";
  }



  template class MeshParts<2>;
  template class MeshParts<3>;
} // namespace VPContact
