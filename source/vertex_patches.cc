// VertexPatches: the patches of a field output from the nodal values at the
// cells' vertices and the cell values.
#include <vpcontact/vertex_patches.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/reference_cell.h>

namespace VPContact
{
  template <int dim>
  void
  VertexPatches<dim>::add_nodal_field(
    const TrilinosWrappers::MPI::Vector &vector,
    const unsigned int                   component,
    const std::string                   &name)
  {
    nodal_fields.push_back({&vector, component});
    nodal_names.push_back(name);
  }



  template <int dim>
  void
  VertexPatches<dim>::mark_last_as_vector(const unsigned int n_components,
                                          const std::string &name)
  {
    AssertThrow(n_components <= nodal_fields.size(), ExcInternalError());
    const unsigned int last = nodal_fields.size() - 1;
    vector_ranges.emplace_back(
      last + 1 - n_components,
      last,
      name,
      DataComponentInterpretation::component_is_part_of_vector);
  }



  template <int dim>
  void
  VertexPatches<dim>::add_cell_field(const Vector<double> &values,
                                     const std::string    &name)
  {
    cell_fields.push_back(&values);
    cell_names.push_back(name);
  }



  template <int dim>
  FieldPatches<dim>
  VertexPatches<dim>::build(const CellHalves<dim>     &cells,
                            const CellKinematics<dim> &kinematics,
                            const bool                 two_threads) const
  {
    constexpr unsigned int n_vertices = GeometryInfo<dim>::vertices_per_cell;
    const unsigned int     n_rows = nodal_fields.size() + cell_fields.size();
    std::vector<const double *> entries;
    for (const auto &field : nodal_fields)
      entries.push_back(kinematics.local_entries(*field.vector));

    FieldPatches<dim>  fields;
    const unsigned int first_of_second_half = cells.half(0).size();
    fields.patches.resize(first_of_second_half + cells.half(1).size());

    // Each half fills the patches of its own cells. The nodes of a cell
    // start with its vertices, in the vertex order of deal.II, which is
    // the order of the points of a patch with one subdivision; values are
    // stored as float, as DataOut does.
    run_in_halves(two_threads, [&](const unsigned int half) {
      std::vector<double> nodal(kinematics.nodes_per_cell());
      unsigned int        patch_index = (half == 0 ? 0 : first_of_second_half);
      for (const auto &cell : cells.half(half))
        {
          DataOutBase::Patch<dim, dim> &patch = fields.patches[patch_index];
          for (unsigned int v = 0; v < n_vertices; ++v)
            patch.vertices[v] = cell->vertex(v);
          patch.patch_index          = patch_index;
          patch.n_subdivisions       = 1;
          patch.points_are_available = false;
          patch.reference_cell       = ReferenceCells::get_hypercube<dim>();
          patch.data.reinit(n_rows, n_vertices);
          for (unsigned int f = 0; f < nodal_fields.size(); ++f)
            {
              kinematics.nodal_values(cell,
                                      entries[f],
                                      nodal_fields[f].component,
                                      make_array_view(nodal));
              // + 0.: a value -0 becomes +0, as in FEValues' sum over
              // the shape functions, which starts from 0.
              for (unsigned int v = 0; v < n_vertices; ++v)
                patch.data(f, v) = static_cast<float>(nodal[v] + 0.);
            }
          for (unsigned int f = 0; f < cell_fields.size(); ++f)
            {
              const float value = static_cast<float>(
                (*cell_fields[f])[cell->active_cell_index()]);
              for (unsigned int v = 0; v < n_vertices; ++v)
                patch.data(nodal_fields.size() + f, v) = value;
            }
          ++patch_index;
        }
      return 0;
    });

    fields.names = nodal_names;
    fields.names.insert(fields.names.end(),
                        cell_names.begin(),
                        cell_names.end());
    fields.vector_ranges = vector_ranges;
    return fields;
  }



  template class VertexPatches<2>;
  template class VertexPatches<3>;
} // namespace VPContact
