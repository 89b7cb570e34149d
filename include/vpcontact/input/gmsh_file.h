// What a Gmsh .msh file holds, read from its bytes without GridIn: whether it
// is binary, the dimension of its cells and the physical tags of its
// boundary elements, for messages that say what is wrong with a user's mesh.
#ifndef vpcontact_gmsh_file_h
#define vpcontact_gmsh_file_h

#include <deal.II/grid/tria.h>

#include <set>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /// Whether @p bytes are a binary Gmsh file (GridIn reads only ASCII).
  bool
  is_binary_gmsh(const std::string &bytes);

  /**
   * The largest cell dimension of the elements of a Gmsh file (formats 2
   * and 4), or 0 where unknown: what a file of tetrahedra read for a 2D
   * scene holds, since GridIn's own message lists only the cell types of
   * the scene's dimension.
   */
  int
  gmsh_cell_dimension(const std::string &bytes);

  /**
   * The physical tags of the elements of dimension @p element_dim in a
   * Gmsh file (formats 2 and 4): the boundary ids GridIn gives the faces
   * it finds there, for @p element_dim one less than the mesh's.
   */
  std::set<int>
  gmsh_physical_tags(const std::string &bytes, const int element_dim);

  /**
   * Throw a message starting with @p source unless every boundary face of
   * @p coarse has a boundary id that @p bytes, the Gmsh file it was read
   * from, gives a boundary element. Gmsh writes only the elements of
   * physical groups, and GridIn gives a boundary face it does not find in
   * the file the id 0: a curve (surface) the user left out of every
   * Physical Curve (Physical Surface) would otherwise be id 0, clamped by
   * the default Clamped boundary ids.
   */
  template <int dim>
  void
  check_gmsh_boundary_tags(const Triangulation<dim> &coarse,
                           const std::string        &bytes,
                           const std::string        &source);
} // namespace VPContact

#endif
