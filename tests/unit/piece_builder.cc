// Unit test: PieceBuilder puts into the .vtu piece what deal.II's DataOut puts
// into its patches, with each vertex once. On a 2D mesh of quadrilaterals with
// hanging nodes, a 2D mesh of triangles, a 3D mesh of hexahedra with hanging
// nodes and a 3D mesh of tetrahedra, serial and on 2 ranks: a linear function
// of each component of a P1/Q1 system (dim displacement components and one
// more, as the damage), its constraints distributed, one component picked by
// a DataPostprocessor, and a field on the cells. For every cell and every
// vertex, the piece's point (through its connectivity, in VTK's order of the
// vertices) lies where the patch has the vertex and carries its values. In 2D
// the connectivity goes round each cell counter-clockwise, as VTK's cells do.
#include <vpcontact/postprocess/piece_builder.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <cstdio>
#include <set>

using namespace VPContact;

namespace
{
  template <int dim>
  class PatchesOf : public DataOut<dim>
  {
  public:
    const std::vector<DataOutBase::Patch<dim, dim>> &
    patches() const
    {
      return this->get_patches();
    }
  };

  // Component c of the field: (c + 1) x + 2 y (+ 3 z) + c.
  template <int dim>
  class Linear : public Function<dim>
  {
  public:
    Linear()
      : Function<dim>(dim + 1)
    {}
    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      double v = c + (c + 1.) * p[0];
      for (unsigned int d = 1; d < dim; ++d)
        v += (d + 1.) * p[d];
      return v;
    }
  };

  // The last component, as the program's contact fields pick one.
  template <int dim>
  class LastComponent : public DataPostprocessorScalar<dim>
  {
  public:
    LastComponent()
      : DataPostprocessorScalar<dim>("picked", update_values)
    {}
    void
    evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                          std::vector<Vector<double>> &computed) const override
    {
      for (unsigned int q = 0; q < computed.size(); ++q)
        computed[q](0) = inputs.solution_values[q](dim);
    }
  };

  // The patches' values against the piece's: the largest difference, and
  // whether any vertex is listed twice or a 2D cell goes round clockwise.
  template <int dim>
  void
  compare(const std::vector<DataOutBase::Patch<dim, dim>> &patches,
          const VtuPiece                                  &piece,
          const ReferenceCell                             &kind,
          double                                          &largest,
          unsigned int                                    &wrong)
  {
    static const unsigned int    lexicographic[] = {0, 1, 3, 2, 4, 5, 7, 6};
    std::set<std::vector<float>> positions;
    for (std::size_t p = 0; p < piece.n_points(); ++p)
      positions.insert(
        {piece.points.begin() + 3 * p, piece.points.begin() + 3 * p + 3});
    wrong += positions.size() != piece.n_points();
    wrong += patches.size() != piece.n_cells();
    const unsigned int n = kind.n_vertices();
    for (std::size_t k = 0; k < patches.size(); ++k)
      {
        double area = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int v = kind.is_hyper_cube() ? lexicographic[i] : i;
            const std::size_t  p = piece.connectivity[k * n + i];
            for (unsigned int d = 0; d < dim; ++d)
              largest = std::max<double>(largest,
                                         std::abs(patches[k].vertices[v][d]
                                                  - piece.points[3 * p + d]));
            for (unsigned int c = 0; c <= dim; ++c)
              {
                const auto &field
                  = c < dim ? piece.point_fields[0] : piece.point_fields[1];
                const float value
                  = c < dim ? field.values[3 * p + c] : field.values[p];
                largest
                  = std::max<double>(largest,
                                     std::abs(patches[k].data(c, v) - value));
              }
            largest
              = std::max<double>(largest,
                                 std::abs(patches[k].data(dim + 1, v)
                                          - piece.point_fields[2].values[p]));
            const std::size_t q = piece.connectivity[k * n + (i + 1) % n];
            area += piece.points[3 * p] * piece.points[3 * q + 1]
                    - piece.points[3 * q] * piece.points[3 * p + 1];
          }
        wrong += dim == 2 && area <= 0;
        largest = std::max<double>(largest,
                                   std::abs(patches[k].data(dim + 2, 0)
                                            - piece.cell_fields[0].values[k]));
      }
  }



  template <int dim>
  void
  check(const std::string &name, const bool simplex)
  {
    const MPI_Comm                      comm = MPI_COMM_WORLD;
    std::unique_ptr<Triangulation<dim>> mesh;
    std::unique_ptr<FiniteElement<dim>> fe;
    std::unique_ptr<Mapping<dim>>       mapping;
    if (simplex)
      {
        mesh = std::make_unique<parallel::shared::Triangulation<dim>>(comm);
        GridGenerator::subdivided_hyper_cube_with_simplices(*mesh, 3);
        fe      = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(1), dim + 1);
        mapping = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
      }
    else
      {
        mesh
          = std::make_unique<parallel::distributed::Triangulation<dim>>(comm);
        GridGenerator::subdivided_hyper_cube(*mesh, 3);
        mesh->begin_active()->set_refine_flag();
        mesh->execute_coarsening_and_refinement();
        fe
          = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
        mapping = std::make_unique<MappingQ<dim>>(1);
      }
    DoFHandler<dim> dofs(*mesh);
    dofs.distribute_dofs(*fe);
    const IndexSet owned    = dofs.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dofs);
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    constraints.close();

    LA::MPI::Vector field(owned, comm);
    VectorTools::interpolate(*mapping, dofs, Linear<dim>(), field);
    constraints.distribute(field);
    LA::MPI::Vector ghosted(owned, relevant, comm);
    ghosted = field;
    Vector<double> on_cells(mesh->n_active_cells());
    for (const auto &cell : mesh->active_cell_iterators())
      on_cells[cell->active_cell_index()] = cell->center()[0];

    std::vector<std::string> names(dim, "u");
    names.push_back("zeta");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    const LastComponent<dim> picked;

    PatchesOf<dim> data_out;
    data_out.attach_dof_handler(dofs);
    data_out.add_data_vector(ghosted,
                             names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    data_out.add_data_vector(ghosted, picked);
    data_out.add_data_vector(on_cells, "x_of_centre");
    data_out.build_patches(*mapping);

    PieceBuilder<dim> builder(dofs, ghosted);
    builder.add_point_fields(ghosted, names, interpretation);
    builder.add_point_fields(ghosted, picked);
    builder.add_cell_field(on_cells, "x_of_centre");
    const FieldPiece piece = builder.take();

    double       largest = 0;
    unsigned int wrong   = 0;
    compare(data_out.patches(),
            piece.piece,
            mesh->begin_active()->reference_cell(),
            largest,
            wrong);
    largest                  = Utilities::MPI::max(largest, comm);
    wrong                    = Utilities::MPI::sum(wrong, comm);
    const unsigned int cells = Utilities::MPI::sum(piece.piece.n_cells(), comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // Positions in single precision, as VTK's files hold them.
        std::printf("%s: %u cells; the values of DataOut's patches to 1e-6: "
                    "%s; vertices twice or cells clockwise: %u\n",
                    name.c_str(),
                    cells,
                    largest <= 1e-6 ?
                      "yes" :
                      ("NO, " + std::to_string(largest)).c_str(),
                    wrong);
        std::printf("  point fields:");
        for (const auto &f : piece.piece.point_fields)
          std::printf(" %s (%u)", f.name.c_str(), f.n_components);
        std::printf("; names for the record:");
        for (const auto &n : piece.names)
          std::printf(" %s", n.c_str());
        std::printf("; vectors: %zu\n", piece.vector_ranges.size());
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("quadrilaterals, hanging nodes", false);
  check<2>("triangles", true);
  check<3>("hexahedra, hanging nodes", false);
  check<3>("tetrahedra", true);
}
