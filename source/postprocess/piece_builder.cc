// PieceBuilder: the rank's cells and the nodal fields at their vertices as a
// .vtu piece.
#include <vpcontact/postprocess/piece_builder.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <algorithm>
#include <utility>

namespace VPContact
{
  namespace
  {
    // VTK's order of a cell's vertices, from deal.II's: lexicographic for
    // quadrilaterals and hexahedra (VTK goes round each face), the same
    // for triangles and tetrahedra.
    const unsigned int *
    vtk_vertex_order(const ReferenceCell &kind)
    {
      static const unsigned int lexicographic[] = {0, 1, 3, 2, 4, 5, 7, 6};
      static const unsigned int same[]          = {0, 1, 2, 3};
      return kind.is_hyper_cube() ? lexicographic : same;
    }



    // A linear element with every degree of freedom on a vertex, the
    // components of a vertex in order: what reading the nodal values at
    // the vertices needs.
    template <int dim>
    void
    check_vertex_element(const FiniteElement<dim> &fe)
    {
      bool linear = fe.n_dofs_per_cell()
                      == fe.reference_cell().n_vertices() * fe.n_components()
                    && fe.n_dofs_per_vertex() == fe.n_components();
      for (unsigned int i = 0; linear && i < fe.n_dofs_per_cell(); ++i)
        linear = fe.system_to_component_index(i).first == i % fe.n_components();
      AssertThrow(linear,
                  ExcMessage("The field output reads nodal values at the "
                             "vertices: it needs P1/Q1 elements, not "
                             + fe.get_name() + "."));
    }

    /// The number of locally owned cells and of their vertices, counted
    /// once per cell.
    template <int dim>
    std::pair<std::size_t, std::size_t>
    count_owned_corners(const DoFHandler<dim> &dof_handler)
    {
      std::size_t n_cells = 0, n_corners = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            ++n_cells;
            n_corners += cell->n_vertices();
          }
      return {n_cells, n_corners};
    }
  } // namespace



  template <int dim>
  PieceBuilder<dim>::PieceBuilder(const DoFHandler<dim> &dof_handler,
                                  const LA::MPI::Vector &layout)
    : n_components(dof_handler.get_fe().n_components())
    , layout_data(layout.trilinos_vector().Map().DataPtr())
  {
    check_vertex_element(dof_handler.get_fe());
    const auto               &map = layout.trilinos_vector().Map();
    std::vector<unsigned int> point_of_vertex(
      dof_handler.get_triangulation().n_vertices(),
      numbers::invalid_unsigned_int);
    std::vector<types::global_dof_index> dofs;
    VtuPiece                            &piece = fields.piece;
    // The cells' lists sized as they will end; the points' (not known
    // before the loop) lose the spare capacity of their growth after it.
    // The piece lives while the fields are written, at the peak of a run's
    // memory.
    const auto [n_cells, n_corners] = count_owned_corners(dof_handler);
    piece.connectivity.reserve(n_corners);
    piece.offsets.reserve(n_cells);
    piece.types.reserve(n_cells);
    cell_indices.reserve(n_cells);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          const unsigned int *order = vtk_vertex_order(cell->reference_cell());
          for (const unsigned int i : cell->vertex_indices())
            {
              const unsigned int v     = order[i];
              unsigned int      &point = point_of_vertex[cell->vertex_index(v)];
              if (point == numbers::invalid_unsigned_int)
                {
                  point = positions.size();
                  positions.push_back(cell->vertex(v));
                  for (unsigned int c = 0; c < n_components; ++c)
                    {
                      const int entry = map.LID(
                        static_cast<TrilinosWrappers::types::int_type>(
                          dofs[v * n_components + c]));
                      Assert(entry >= 0,
                             ExcMessage("The layout lacks a node of an "
                                        "owned cell."));
                      point_entries.push_back(entry);
                    }
                }
              piece.connectivity.push_back(point);
            }
          piece.offsets.push_back(piece.connectivity.size());
          piece.types.push_back(cell->reference_cell().vtk_linear_type());
          cell_indices.push_back(cell->active_cell_index());
        }
    positions.shrink_to_fit();
    point_entries.shrink_to_fit();
    piece.points.reserve(3 * positions.size());
    for (const auto &position : positions)
      for (unsigned int d = 0; d < 3; ++d)
        piece.points.push_back(d < dim ? position[d] : 0.f);
  }



  template <int dim>
  const double *
  PieceBuilder<dim>::entries_of(const LA::MPI::Vector &vector) const
  {
    AssertThrow(vector.trilinos_vector().Map().DataPtr() == layout_data,
                ExcMessage("A field for the output has another layout than "
                           "the one its PieceBuilder was made with."));
    return vector.trilinos_vector()[0];
  }



  template <int dim>
  void
  PieceBuilder<dim>::add_point_fields(
    const LA::MPI::Vector          &vector,
    const std::vector<std::string> &names,
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      &interpretation)
  {
    AssertDimension(names.size(), n_components);
    const double *entries = entries_of(vector);
    add_columns(names,
                interpretation,
                [&](const std::size_t p, const unsigned int k) {
                  return entries[point_entries[p * n_components + k]];
                });
  }



  template <int dim>
  void
  PieceBuilder<dim>::add_point_fields(
    const LA::MPI::Vector        &vector,
    const DataPostprocessor<dim> &postprocessor)
  {
    AssertThrow((postprocessor.get_needed_update_flags()
                 & ~(update_values | update_quadrature_points))
                  == update_default,
                ExcMessage("The field output evaluates postprocessors at the "
                           "vertices from values alone."));
    const double      *entries   = entries_of(vector);
    const auto         names     = postprocessor.get_names();
    const std::size_t  n_points  = positions.size();
    const unsigned int n_outputs = names.size();
    // In batches, so that the postprocessor's virtual call and its vectors
    // are shared by many points.
    const std::size_t                    batch = 256;
    std::vector<double>                  computed_values(n_points * n_outputs);
    DataPostprocessorInputs::Vector<dim> inputs;
    std::vector<Vector<double>>          computed;
    for (std::size_t first = 0; first < n_points; first += batch)
      {
        const std::size_t n = std::min(batch, n_points - first);
        inputs.solution_values.resize(n, Vector<double>(n_components));
        inputs.evaluation_points.assign(positions.begin() + first,
                                        positions.begin() + first + n);
        computed.resize(n, Vector<double>(n_outputs));
        for (std::size_t q = 0; q < n; ++q)
          for (unsigned int c = 0; c < n_components; ++c)
            inputs.solution_values[q][c]
              = entries[point_entries[(first + q) * n_components + c]];
        postprocessor.evaluate_vector_field(inputs, computed);
        for (std::size_t q = 0; q < n; ++q)
          for (unsigned int k = 0; k < n_outputs; ++k)
            computed_values[(first + q) * n_outputs + k] = computed[q][k];
      }
    add_columns(names,
                postprocessor.get_data_component_interpretation(),
                [&](const std::size_t p, const unsigned int k) {
                  return computed_values[p * n_outputs + k];
                });
  }



  template <int dim>
  template <typename ValueAt>
  void
  PieceBuilder<dim>::add_columns(
    const std::vector<std::string> &names,
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
                  &interpretation,
    const ValueAt &value)
  {
    using DataComponentInterpretation::component_is_part_of_vector;
    AssertDimension(interpretation.size(), names.size());
    const std::size_t n_points = positions.size();
    for (unsigned int k = 0; k < names.size();)
      {
        // A vector: the run of components with its name (written with 3
        // components, as VTK reads vectors; z = 0 in 2D).
        unsigned int n = 1;
        if (interpretation[k] == component_is_part_of_vector)
          while (k + n < names.size() && names[k + n] == names[k]
                 && interpretation[k + n] == component_is_part_of_vector)
            ++n;
        AssertThrow(n <= 3,
                    ExcMessage("A vector field of more than 3 components."));
        VtuPiece::Field field;
        field.name = names[k];
        field.n_components
          = interpretation[k] == component_is_part_of_vector ? 3 : 1;
        field.values.resize(n_points * field.n_components, 0.f);
        for (std::size_t p = 0; p < n_points; ++p)
          for (unsigned int j = 0; j < n; ++j)
            field.values[p * field.n_components + j] = value(p, k + j);
        if (field.n_components == 3)
          fields.vector_ranges.emplace_back(fields.names.size(),
                                            fields.names.size() + n - 1,
                                            names[k],
                                            component_is_part_of_vector);
        for (unsigned int j = 0; j < n; ++j)
          fields.names.push_back(names[k]);
        fields.piece.point_fields.push_back(std::move(field));
        k += n;
      }
  }



  template <int dim>
  void
  PieceBuilder<dim>::add_cell_field(const Vector<double> &values,
                                    const std::string    &name)
  {
    VtuPiece::Field field;
    field.name = name;
    field.values.reserve(cell_indices.size());
    for (const unsigned int index : cell_indices)
      field.values.push_back(values[index]);
    fields.piece.cell_fields.push_back(std::move(field));
    fields.cell_names.push_back(name);
  }



  template <int dim>
  FieldPiece
  PieceBuilder<dim>::take()
  {
    return std::move(fields);
  }



  template class PieceBuilder<2>;
  template class PieceBuilder<3>;
} // namespace VPContact
