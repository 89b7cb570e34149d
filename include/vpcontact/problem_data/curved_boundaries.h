// The curved parts of the body's boundary (Geometry/Curved boundaries):
// manifolds attached to boundary ids, so that refinement puts new vertices
// on the true circle, sphere or cylinder instead of on the coarse facets.
#ifndef vpcontact_curved_boundaries_h
#define vpcontact_curved_boundaries_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Entries "Curved boundaries" and "Interior manifold" of the section
   * Geometry. Each listed boundary id gets a manifold with the id as its
   * manifold id:
   * - sphere(x0, y0[, z0]): a circle in 2D, a sphere in 3D, about the
   *   centre (deal.II's SphericalManifold);
   * - cylinder(x0, y0, z0, dx, dy, dz) (3D): the cylinder about the axis
   *   through (x0, y0, z0) along (dx, dy, dz) (CylindricalManifold).
   * With "Interior manifold = transfinite" (the default) the cells of a
   * quadrilateral or hexahedral mesh with a curved boundary get deal.II's
   * TransfiniteInterpolationManifold, which blends the curved faces into
   * the interior, so that refined cells near a curved boundary stay well
   * shaped (step-65). Meshes of simplices keep straight interiors.
   */
  template <int dim>
  class CurvedBoundaries
  {
  public:
    /// The entries, in the current subsection (Geometry).
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read them; a malformed shape is refused naming the entry.
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Attach the manifolds to the coarse mesh @p triangulation (before any
     * refinement). A listed id the mesh does not have is refused, naming
     * the entry and the ids the mesh has. Collective on a distributed
     * mesh.
     */
    void
    attach(Triangulation<dim> &triangulation) const;

    bool
    empty() const;

  private:
    struct Shape
    {
      enum class Kind
      {
        sphere,
        cylinder
      } kind;
      Point<dim>     centre;
      Tensor<1, dim> direction;
      std::string    text;
    };

    Shape
    parse_shape(const std::string &text, const std::string &value) const;

    std::map<types::boundary_id, Shape> shapes;
    bool                                transfinite_interior = true;
  };
} // namespace VPContact

#endif
