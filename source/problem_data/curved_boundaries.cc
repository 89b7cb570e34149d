// CurvedBoundaries: manifolds on boundary ids, and the transfinite
// interpolation that carries them into the interior.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parsed_function.h>
#include <vpcontact/problem_data/curved_boundaries.h>

#include <deal.II/base/utilities.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <set>

namespace VPContact
{
  namespace
  {
    const std::string entry = "Geometry/Curved boundaries";

    /// The manifold id of the transfinite interpolation of the cells: above
    /// every boundary id (at most 254), which the curved faces take.
    constexpr types::manifold_id interior_manifold_id = 1000;
  } // namespace



  template <int dim>
  void
  CurvedBoundaries<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Curved boundaries",
      "",
      Patterns::Anything(),
      "Boundary ids whose faces lie on a curved surface, as 'id: shape' "
      "pairs separated by commas: 'sphere(x0, y0)' a circle about (x0, y0) "
      "in 2D, 'sphere(x0, y0, z0)' a sphere in 3D, 'cylinder(x0, y0, z0, "
      "dx, dy, dz)' (3D) the cylinder about the axis through (x0, y0, z0) "
      "along (dx, dy, dz); e.g. '4: sphere(0.5, 0.5)'. Refinement then puts "
      "new vertices on the surface, not on the coarse mesh's facets. Empty: "
      "every boundary is flat between its vertices.");
    prm.declare_entry(
      "Interior manifold",
      "transfinite",
      Patterns::Selection("transfinite|none"),
      "With curved boundaries on quadrilaterals (hexahedra): 'transfinite' "
      "blends the curved faces into the cells (deal.II's "
      "TransfiniteInterpolationManifold, as in step-65), so that refined "
      "cells near the curve stay well shaped; 'none' refines the interior "
      "cells straight, which only suits curves meshed finely already. "
      "Meshes of triangles (tetrahedra) are refined straight inside.");
  }



  template <int dim>
  void
  CurvedBoundaries<dim>::parse_parameters(ParameterHandler &prm)
  {
    shapes.clear();
    const std::string value = prm.get("Curved boundaries");
    for (const std::string &pair : split_outside_parentheses(value))
      {
        const auto colon = pair.find(':');
        VPContactCheckParameter(colon != std::string::npos,
                                entry,
                                value,
                                "expected 'id: shape' pairs separated by "
                                "commas, e.g. '4: sphere(0.5, 0.5)'.");
        int id = -1;
        try
          {
            id = Utilities::string_to_int(
              Utilities::trim(pair.substr(0, colon)));
          }
        catch (...)
          {}
        VPContactCheckParameter(id >= 0 && id <= 254,
                                entry,
                                value,
                                "'" + pair.substr(0, colon)
                                  + "' is no boundary id (an integer in [0, "
                                    "254]).");
        VPContactCheckParameter(
          shapes.emplace(id, parse_shape(pair.substr(colon + 1), value)).second,
          entry,
          value,
          "boundary id " + std::to_string(id) + " is listed twice.");
      }
    transfinite_interior = (prm.get("Interior manifold") == "transfinite");
  }



  template <int dim>
  typename CurvedBoundaries<dim>::Shape
  CurvedBoundaries<dim>::parse_shape(const std::string &text,
                                     const std::string &value) const
  {
    const std::string shape_text = Utilities::trim(text);
    const auto        open       = shape_text.find('(');
    const std::string name       = Utilities::trim(shape_text.substr(0, open));
    const bool closed = open != std::string::npos && shape_text.back() == ')';
    std::vector<double> numbers;
    try
      {
        if (closed)
          numbers = Utilities::string_to_double(Utilities::split_string_list(
            shape_text.substr(open + 1, shape_text.size() - open - 2)));
      }
    catch (...)
      {
        numbers.clear();
      }
    Shape shape;
    shape.text = shape_text;
    if (name == "sphere" && numbers.size() == dim)
      {
        shape.kind = Shape::Kind::sphere;
        for (unsigned int d = 0; d < dim; ++d)
          shape.centre[d] = numbers[d];
        return shape;
      }
    const bool cylinder
      = (dim == 3 && name == "cylinder" && numbers.size() == 2 * dim);
    VPContactCheckParameter(cylinder,
                            entry,
                            value,
                            "'" + shape_text + "' is no shape: expected "
                              + (dim == 2 ? "sphere(x0, y0) (a circle)" :
                                            "sphere(x0, y0, z0) or "
                                            "cylinder(x0, y0, z0, dx, dy, dz)")
                              + ".");
    shape.kind = Shape::Kind::cylinder;
    for (unsigned int d = 0; d < dim; ++d)
      {
        shape.centre[d]    = numbers[d];
        shape.direction[d] = numbers[dim + d];
      }
    VPContactCheckParameter(shape.direction.norm() > 0,
                            entry,
                            value,
                            "the axis direction of '" + shape_text
                              + "' is zero.");
    return shape;
  }



  template <int dim>
  void
  CurvedBoundaries<dim>::attach(Triangulation<dim> &triangulation) const
  {
    if (shapes.empty())
      return;
    // Every rank holds the whole coarse mesh, also of a distributed mesh.
    std::set<types::boundary_id> mesh_ids;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          mesh_ids.insert(face->boundary_id());
    for (const auto &[id, shape] : shapes)
      {
        std::string list;
        for (const auto mesh_id : mesh_ids)
          list += (list.empty() ? "" : ",") + std::to_string(mesh_id);
        VPContactCheckParameter(mesh_ids.count(id) == 1,
                                entry,
                                std::to_string(id) + ": " + shape.text,
                                "the mesh has no boundary with this id; its "
                                "boundary ids are {"
                                  + list + "}.");
      }

    // The cells first, then the flat boundary faces, then the curved ones:
    // an edge shared by a flat and a curved face lies on the curve.
    const bool transfinite
      = transfinite_interior
        && !triangulation.begin()->reference_cell().is_simplex();
    if (transfinite)
      triangulation.set_all_manifold_ids(interior_manifold_id);
    for (const bool curved : {false, true})
      for (const auto &cell : triangulation.cell_iterators_on_level(0))
        for (const auto &face : cell->face_iterators())
          {
            if (!face->at_boundary()
                || (shapes.count(face->boundary_id()) == 1) != curved)
              continue;
            if (curved)
              face->set_all_manifold_ids(face->boundary_id());
            else if (transfinite)
              face->set_all_manifold_ids(numbers::flat_manifold_id);
          }

    for (const auto &[id, shape] : shapes)
      if (shape.kind == Shape::Kind::sphere)
        triangulation.set_manifold(id, SphericalManifold<dim>(shape.centre));
      else if constexpr (dim == 3)
        triangulation.set_manifold(id,
                                   CylindricalManifold<dim>(shape.direction,
                                                            shape.centre));
    if (transfinite)
      {
        TransfiniteInterpolationManifold<dim> interior;
        interior.initialize(triangulation);
        triangulation.set_manifold(interior_manifold_id, interior);
      }
  }



  template <int dim>
  bool
  CurvedBoundaries<dim>::empty() const
  {
    return shapes.empty();
  }



  template class CurvedBoundaries<2>;
  template class CurvedBoundaries<3>;
} // namespace VPContact
