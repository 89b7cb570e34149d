// Whether a cell is another one moved without turning or deforming it, so
// that whatever a linear mapping gives on one (Jacobians, shape gradients,
// an elastic cell matrix) holds on the other.
#ifndef vpcontact_fe_cell_translation_h
#define vpcontact_fe_cell_translation_h

#include <deal.II/base/tensor.h>

#include <algorithm>

namespace VPContact
{
  using namespace dealii;

  /**
   * True if the vertices of @p cell lie where those of @p reference lie,
   * moved by one vector: the offset of each vertex from the first is that
   * of @p reference to 1e-12 of the reference's largest offset. Both cells
   * must have the same kind and number of vertices.
   *
   * deal.II's TriaAccessor::is_translation_of() measures the tolerance
   * against the distance between the two cells instead, which for small
   * cells far apart lets through shapes that differ by more than the
   * solver's tolerance; here it is measured against the cell itself. The
   * vertices of a subdivided box, computed as a corner plus multiples of
   * the cell size, repeat each other's offsets to about 1e-15 of the size.
   */
  template <typename CellIterator>
  bool
  is_translate(const CellIterator &cell, const CellIterator &reference)
  {
    const unsigned int n_vertices = reference->n_vertices();
    if (cell->n_vertices() != n_vertices)
      return false;
    double size_square = 0.;
    for (unsigned int v = 1; v < n_vertices; ++v)
      size_square
        = std::max(size_square,
                   (reference->vertex(v) - reference->vertex(0)).norm_square());
    const double tolerance_square = 1e-24 * size_square;
    for (unsigned int v = 1; v < n_vertices; ++v)
      {
        const auto difference = (cell->vertex(v) - cell->vertex(0))
                                - (reference->vertex(v) - reference->vertex(0));
        if (difference.norm_square() > tolerance_square)
          return false;
      }
    return true;
  }
} // namespace VPContact

#endif
