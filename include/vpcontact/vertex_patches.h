// The patches of a field output taken from the values at the cells'
// vertices, as deal.II's DataOut builds them, without its FEValues.
#ifndef vpcontact_vertex_patches_h
#define vpcontact_vertex_patches_h

#include <vpcontact/cell_halves.h>
#include <vpcontact/cell_kinematics.h>
#include <vpcontact/field_writer.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The fields of one output, on one patch per locally owned cell with its
   * data at the cell's vertices: what DataOut::build_patches() makes of
   * the simulator's nodal and cell vectors with one subdivision and no
   * curved cells (its default). The .vtu written from these patches is
   * the same, byte for byte, as the one from DataOut (unit test
   * vertex_patches).
   *
   * Why not DataOut: it evaluates every field through an FEValues on
   * every cell, allocating as it goes, to obtain what for a Lagrange
   * element are the nodal values at the vertices themselves. At 512^2
   * cells that was about 0.3 s per output in the main thread (in the
   * paper scene, eleven outputs). Here the values are read at the nodes'
   * positions kept by CellKinematics, in two threads where
   * Solver/Second thread allows it.
   *
   * The order of the data sets is DataOut's: the nodal fields in the
   * order they were added, then the cell fields.
   */
  template <int dim>
  class VertexPatches
  {
  public:
    /// Component @p component of @p vector, a ghosted vector in the
    /// layout of the simulator's solution; kept by reference until
    /// build().
    void
    add_nodal_field(const TrilinosWrappers::MPI::Vector &vector,
                    const unsigned int                   component,
                    const std::string                   &name);

    /// The nodal fields added last, @p n_components of them, form the
    /// vector @p name (the displacement: ParaView shows it as a vector).
    void
    mark_last_as_vector(const unsigned int n_components,
                        const std::string &name);

    /// One value per active cell, by active cell index; kept by
    /// reference until build().
    void
    add_cell_field(const Vector<double> &values, const std::string &name);

    /// The patches of the locally owned cells, in their order.
    FieldPatches<dim>
    build(const CellHalves<dim>     &cells,
          const CellKinematics<dim> &kinematics,
          const bool                 two_threads) const;

  private:
    struct NodalField
    {
      const TrilinosWrappers::MPI::Vector *vector;
      unsigned int                         component;
    };

    std::vector<NodalField>             nodal_fields;
    std::vector<const Vector<double> *> cell_fields;
    std::vector<std::string>            nodal_names;
    std::vector<std::string>            cell_names;
    VectorRanges                        vector_ranges;
  };
} // namespace VPContact

#endif
