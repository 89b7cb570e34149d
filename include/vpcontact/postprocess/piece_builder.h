// The fields of the rank's cells, taken at their vertices, as the .vtu piece
// of a field output (VtuPiece): the P1/Q1 fields of this program need no
// evaluation inside the cells, so the piece reads the nodal values.
#ifndef vpcontact_piece_builder_h
#define vpcontact_piece_builder_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/postprocess/field_writer.h>
#include <vpcontact/postprocess/vtu_piece.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Builds the piece of one field output from the rank's locally owned
   * cells: each vertex once, in the order the cells first reach it, with
   * the cells' connectivity in VTK's vertex order. Point fields read the
   * values of a ghosted nodal vector at each vertex, directly or through a
   * DataPostprocessor (one that asks for values only, as those of the
   * physics objects do); cell fields take one value per cell. The values at
   * a vertex are the nodal values DataOut's patches also show there: the
   * finite element is linear and has all its degrees of freedom on the
   * vertices (the constructor checks this).
   *
   * The names and vector ranges it collects are those of deal.II's
   * DataOut for the same fields, for the .pvtu record.
   */
  template <int dim>
  class PieceBuilder
  {
  public:
    /**
     * The owned cells of @p dof_handler and their vertices. @p layout is a
     * ghosted vector on the DoFHandler's degrees of freedom with the nodes
     * of every owned cell; every vector given later must have its layout
     * (be a copy of it, or of a vector of the same layout).
     */
    PieceBuilder(const DoFHandler<dim> &dof_handler,
                 const LA::MPI::Vector &layout);

    /**
     * The components of @p vector at the vertices as point fields, one name
     * and interpretation per component of the finite element, as
     * DataOut::add_data_vector() takes them: consecutive components marked
     * part of a vector with the same name form a vector field.
     */
    void
    add_point_fields(const LA::MPI::Vector          &vector,
                     const std::vector<std::string> &names,
                     const std::vector<
                       DataComponentInterpretation::DataComponentInterpretation>
                       &interpretation);

    /// The fields @p postprocessor computes from the values of @p vector at
    /// each vertex.
    void
    add_point_fields(const LA::MPI::Vector        &vector,
                     const DataPostprocessor<dim> &postprocessor);

    /// A field constant on each cell: @p values indexed by the active cell
    /// index.
    void
    add_cell_field(const Vector<double> &values, const std::string &name);

    /// The piece and the names of its fields, for a FieldWriter; the
    /// builder is empty afterwards.
    FieldPiece
    take();

  private:
    /// Point fields from @p n_outputs values per point, @p value(p, k)
    /// the k-th at point p, named and grouped as add_point_fields() says.
    template <typename ValueAt>
    void
    add_columns(const std::vector<std::string> &names,
                const std::vector<
                  DataComponentInterpretation::DataComponentInterpretation>
                              &interpretation,
                const ValueAt &value);

    /// The entries of a vector of the layout.
    const double *
    entries_of(const LA::MPI::Vector &vector) const;

    unsigned int n_components;
    /// The layout's map, to check the vectors given.
    const void *layout_data;
    /// For point p, its component c's local entry in vectors of the layout
    /// at p * n_components + c.
    std::vector<int> point_entries;
    /// The position of each point.
    std::vector<Point<dim>> positions;
    /// The active cell index of each cell of the piece.
    std::vector<unsigned int> cell_indices;

    FieldPiece fields;
  };
} // namespace VPContact

#endif
