// Checks of a mesh before anything computes on it: its cells, and the memory
// the refined mesh needs.
#include <vpcontact/app/memory_limit.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/mesh_checks.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace VPContact
{
  namespace
  {
    // The vertices of a cell as "(x, y), (x, y), ...", for messages.
    template <int dim>
    std::string
    vertices_of(const typename Triangulation<dim>::cell_iterator &cell)
    {
      std::string text;
      for (const unsigned int v : cell->vertex_indices())
        {
          std::ostringstream point;
          point.precision(6);
          point << "(";
          for (unsigned int d = 0; d < dim; ++d)
            point << (d > 0 ? ", " : "") << cell->vertex(v)[d];
          point << ")";
          text += (v > 0 ? ", " : "") + point.str();
        }
      return text;
    }

    // The points where the Jacobian is checked: the Gauss points and the
    // vertices of the reference cell. Only Jacobians are computed there, so
    // the weights do not matter.
    template <int dim>
    Quadrature<dim>
    jacobian_check_points(const ReferenceCell &cell)
    {
      std::vector<Point<dim>> points
        = cell.get_gauss_type_quadrature<dim>(2).get_points();
      for (const unsigned int v : cell.vertex_indices())
        points.push_back(cell.vertex<dim>(v));
      return Quadrature<dim>(points, std::vector<double>(points.size(), 1.));
    }

    // The least memory [bytes] one active cell of this program takes: the
    // mesh, the DoF numbering, the stress history at the quadrature points,
    // the vectors and the sparse matrix of the displacement and damage
    // problems. Lower bounds, well below what a run takes (see
    // doc/input_checks.md), so that only meshes that certainly cannot fit
    // are refused.
    constexpr double bytes_per_active_cell_2d = 2000;
    constexpr double bytes_per_active_cell_3d = 10000;
    // Every rank holds the whole coarse mesh, in deal.II's triangulation
    // and in p4est's connectivity.
    constexpr double bytes_per_coarse_cell = 500;
    // A mesh of simplices lives whole on every rank (deal.II's shared
    // triangulation): its cells, faces and vertices and the DoFHandler's
    // indices of every cell; what a rank holds of its own cells is less
    // than on quadrilaterals, with fewer nodes per cell. Lower bounds too.
    constexpr double bytes_per_shared_cell_2d   = 950;
    constexpr double bytes_per_shared_cell_3d   = 1200;
    constexpr double bytes_per_owned_simplex_2d = 450;
    constexpr double bytes_per_owned_simplex_3d = 1000;

    // The vertices on the boundary of the mesh as (x, index) pairs, sorted
    // by x.
    template <int dim>
    std::vector<std::pair<double, unsigned int>>
    boundary_vertices_by_x(const Triangulation<dim> &triangulation)
    {
      const std::vector<Point<dim>> &vertices = triangulation.get_vertices();
      std::vector<bool>              on_boundary(vertices.size(), false);
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          for (const unsigned int v : face->vertex_indices())
            on_boundary[face->vertex_index(v)] = true;
      std::vector<std::pair<double, unsigned int>> by_x;
      for (unsigned int i = 0; i < vertices.size(); ++i)
        if (on_boundary[i])
          by_x.emplace_back(vertices[i][0], i);
      std::sort(by_x.begin(), by_x.end());
      return by_x;
    }

    // The unit normal of a face's line (2D) or plane (3D), which passes
    // through its centre.
    template <int dim>
    Tensor<1, dim>
    unit_normal(const typename Triangulation<dim>::face_iterator &face)
    {
      Tensor<1, dim> normal;
      if (dim == 2)
        {
          const Tensor<1, dim> t = face->vertex(1) - face->vertex(0);
          normal[0]              = -t[1];
          normal[1]              = t[0];
        }
      else if (face->n_vertices() == 3)
        normal = cross_product_3d(face->vertex(1) - face->vertex(0),
                                  face->vertex(2) - face->vertex(0));
      else
        normal = cross_product_3d(face->vertex(3) - face->vertex(0),
                                  face->vertex(2) - face->vertex(1));
      normal /= normal.norm();
      return normal;
    }

    // Whether @p p, a point of the plane of the triangle @p face, lies in the
    // triangle (to @p tolerance): its barycentric coordinates are all
    // non-negative.
    template <int dim>
    bool
    in_triangle(const typename Triangulation<dim>::face_iterator &face,
                const Point<dim>                                 &p,
                const double                                      tolerance)
    {
      const Tensor<1, dim> a  = face->vertex(1) - face->vertex(0);
      const Tensor<1, dim> b  = face->vertex(2) - face->vertex(0);
      const Tensor<1, dim> x  = p - face->vertex(0);
      const double         aa = a * a, ab = a * b, bb = b * b;
      const double         det      = aa * bb - ab * ab;
      const double         s        = (bb * (x * a) - ab * (x * b)) / det;
      const double         t        = (aa * (x * b) - ab * (x * a)) / det;
      const double         relative = tolerance / face->diameter();
      return s > -relative && t > -relative && s + t < 1 + relative;
    }

    // Throw if a vertex of the mesh lies inside a boundary face of another
    // cell: two cells that do not share the whole face, so that the body
    // is cut along it (deal.II takes such a face for boundary, and p4est
    // cannot order such a mesh on several ranks). Only boundary vertices
    // can do this, and only boundary faces can hold them; the vertices are
    // sorted by x so that each face looks at those within its extent.
    template <int dim>
    void
    check_conforming(const Triangulation<dim> &triangulation,
                     const std::string        &source)
    {
      const std::vector<Point<dim>> &vertices = triangulation.get_vertices();
      const auto by_x = boundary_vertices_by_x(triangulation);
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          {
            const double tolerance = 1e-10 * face->diameter();
            Point<dim>   lower = face->vertex(0), upper = face->vertex(0);
            for (const unsigned int v : face->vertex_indices())
              for (unsigned int d = 0; d < dim; ++d)
                {
                  lower[d] = std::min(lower[d], face->vertex(v)[d]);
                  upper[d] = std::max(upper[d], face->vertex(v)[d]);
                }
            // The face's line (2D) or plane (3D): a point and a unit normal.
            const Point<dim>     centre = face->center();
            const Tensor<1, dim> normal = unit_normal<dim>(face);
            for (auto it
                 = std::lower_bound(by_x.begin(),
                                    by_x.end(),
                                    std::make_pair(lower[0] - tolerance, 0u));
                 it != by_x.end() && it->first <= upper[0] + tolerance;
                 ++it)
              {
                const Point<dim> &p      = vertices[it->second];
                bool              inside = true;
                for (const unsigned int v : face->vertex_indices())
                  inside = inside && face->vertex_index(v) != it->second;
                for (unsigned int d = 0; d < dim; ++d)
                  inside = inside && p[d] > lower[d] - tolerance
                           && p[d] < upper[d] + tolerance;
                // A triangle covers only half of its bounding box.
                if (inside && face->n_vertices() == 3)
                  inside = in_triangle<dim>(face, p, tolerance);
                AssertThrow(
                  !inside || std::abs((p - centre) * normal) > tolerance,
                  ExcMessage(
                    source + ": the vertex (" + to_text(p[0]) + ", "
                    + to_text(p[1])
                    + (dim == 3 ? ", " + to_text(p[dim - 1]) : std::string())
                    + ") lies inside a face of another "
                      "cell: the cells there do not share "
                      "whole faces (a hanging vertex), and "
                      "the body would be cut along that "
                      "face. Mesh it so that neighbouring "
                      "cells share their faces."));
              }
          }
    }

    std::string
    gigabytes(const double bytes)
    {
      return to_text(std::round(bytes / 1e8) / 10) + " GB";
    }
  } // namespace



  template <int dim>
  void
  check_mesh_cells(const Triangulation<dim> &triangulation,
                   const std::string        &source)
  {
    AssertThrow(triangulation.n_active_cells() > 0,
                ExcMessage(source + ": the mesh has no cells of dimension "
                           + std::to_string(dim)
                           + ". Check the file and Dimension."));
    // One kind of cell: quadrilaterals (hexahedra) or triangles
    // (tetrahedra). Prisms, pyramids and mixed meshes have no element here.
    const ReferenceCell kind = triangulation.begin_active()->reference_cell();
    for (const auto &cell : triangulation.active_cell_iterators())
      AssertThrow(cell->reference_cell() == kind
                    && (kind.is_hyper_cube() || kind.is_simplex()),
                  ExcMessage(
                    source + ": the mesh has cells of more than one kind, or "
                    + "prisms or pyramids (the first at "
                    + vertices_of<dim>(cell) + "); this program computes on "
                    + (dim == 2 ? "quadrilaterals or on triangles" :
                                  "hexahedra or on tetrahedra")
                    + ", one kind per mesh. Mesh the body with one kind (in "
                      "Gmsh: Mesh.RecombineAll = 1 for quadrilaterals)."));

    check_conforming(triangulation, source);

    // The linear mapping of the cell kind; the element only serves FEValues
    // (which keeps a reference to it).
    const std::unique_ptr<FiniteElement<dim>> fe
      = kind.is_simplex() ?
          std::unique_ptr<FiniteElement<dim>>(new FE_SimplexP<dim>(1)) :
          std::unique_ptr<FiniteElement<dim>>(new FE_Q<dim>(1));
    FEValues<dim> fe_values(get_default_linear_mapping(triangulation),
                            *fe,
                            jacobian_check_points<dim>(kind),
                            update_jacobians);
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        fe_values.reinit(cell);
        // Relative to the size of the cell: a Jacobian that is a rounding
        // error of the cell's measure is a degenerate cell.
        const double scale = std::pow(cell->diameter(), dim);
        for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
          AssertThrow(
            determinant(Tensor<2, dim>(fe_values.jacobian(q))) > 1e-10 * scale,
            ExcMessage(source + ": the cell with the vertices "
                       + vertices_of<dim>(cell)
                       + " is inverted, degenerate or self-intersecting "
                         "(its Jacobian is not positive everywhere). Check "
                         "the order of its vertices and that no two "
                         "coincide."));
      }
  }



  void
  check_mesh_memory(const unsigned int dim,
                    const double       n_active_cells,
                    const double       n_cells_on_every_rank,
                    const bool         whole_mesh_on_every_rank,
                    const std::string &entries,
                    const MPI_Comm     communicator)
  {
    // What each rank holds: its share of the active cells, and the cells
    // every rank holds (p4est's coarse forest, or a whole shared mesh).
    const double n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const double every_rank_bytes
      = n_cells_on_every_rank
        * (!whole_mesh_on_every_rank ? bytes_per_coarse_cell :
           dim == 2                  ? bytes_per_shared_cell_2d :
                                       bytes_per_shared_cell_3d);
    const double bytes_per_owned_cell
      = whole_mesh_on_every_rank ?
          (dim == 2 ? bytes_per_owned_simplex_2d : bytes_per_owned_simplex_3d) :
          (dim == 2 ? bytes_per_active_cell_2d : bytes_per_active_cell_3d);
    const double rank_bytes
      = every_rank_bytes + n_active_cells * bytes_per_owned_cell / n_ranks;

    // The ranks of a machine share its memory (and usually its cgroup);
    // each rank has its own ulimit. Of the limits passed, the widest is
    // named: the machine's memory before a cgroup before a ulimit.
    MPI_Comm  node;
    const int ierr = MPI_Comm_split_type(communicator,
                                         MPI_COMM_TYPE_SHARED,
                                         0,
                                         MPI_INFO_NULL,
                                         &node);
    AssertThrowMPI(ierr);
    const double ranks_on_node = Utilities::MPI::n_mpi_processes(node);
    MPI_Comm_free(&node);
    const MemoryLimit machine = node_memory_limit();
    const MemoryLimit process = process_memory_limit();
    const int         exceeded
      = Utilities::MPI::max(rank_bytes * ranks_on_node > machine.bytes ?
                              (machine.physical ? 3 : 2) :
                              (rank_bytes > process.bytes ? 1 : 0),
                            communicator);
    if (exceeded == 0)
      return;
    const MemoryLimit &limit = (exceeded >= 2 ? machine : process);
    std::string        what
      = (exceeded == 3 ?
           "the machines of this run have" :
           limit.source + ", "
             + gigabytes(Utilities::MPI::min(limit.limit, communicator)));
    AssertThrow(
      false,
      ExcMessage(
        entries + ": the mesh would have " + to_text(n_active_cells)
        + " cells, which need at least " + gigabytes(rank_bytes)
        + " of memory on each of the " + to_text(n_ranks) + " rank(s)"
        + (whole_mesh_on_every_rank ?
             " (every rank holds the whole mesh)" :
           every_rank_bytes > 0.1 * rank_bytes ?
             " (every rank holds all " + to_text(n_cells_on_every_rank)
               + " coarse cells)" :
             std::string())
        + ", more than " + what + ". Use fewer cells or refinements"
        + (whole_mesh_on_every_rank ? ", fewer ranks on a machine" : "")
        + (exceeded == 1 ? ", or raise the limit." : ", or more machines.")));
  }



  template void
  check_mesh_cells(const Triangulation<2> &, const std::string &);
  template void
  check_mesh_cells(const Triangulation<3> &, const std::string &);
} // namespace VPContact
