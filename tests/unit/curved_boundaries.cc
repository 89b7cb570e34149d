// Checks Geometry/Curved boundaries: after two global refinements the
// vertices of the hole of prm/meshes/plate_with_hole.msh (2D, a circle of
// radius 0.2 about (1, 0.5)) and of prm/meshes/block_with_hole.msh (3D, a
// cylinder of radius 0.2 about the axis through (1, 0.5) along z) lie on the
// circle and the cylinder to round-off, in quadrilaterals (hexahedra) and in
// triangles (tetrahedra), on every rank's part of the mesh; without the
// entry they lie on the coarse mesh's polygon, inside the circle. A listed
// id the mesh does not have is refused naming the entry.
#include <vpcontact/fe/discretization.h>
#include <vpcontact/problem_data/geometry.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace VPContact;

// The largest distance of a vertex of the faces with boundary id 5 from the
// surface of radius 0.2 about the axis through (1, 0.5) (along z in 3D).
template <int dim>
double
distance_from_hole(const std::string &mesh_file, const std::string &curved)
{
  ParameterHandler prm;
  Geometry<dim>::declare_parameters(prm);
  prm.enter_subsection("Geometry");
  prm.set("Mesh", "file");
  prm.set("Mesh file", mesh_file);
  prm.set("Global refinements", "2");
  prm.set("Curved boundaries", curved);
  prm.leave_subsection();
  Geometry<dim> geometry;
  geometry.parse_parameters(prm, SOURCE_DIR "/../../prm", MPI_COMM_WORLD);
  const Discretization<dim> discretization(geometry.simplex_cells(), false);
  const auto mesh = discretization.make_triangulation(MPI_COMM_WORLD);
  geometry.create_mesh(*mesh);
  double distance = 0;
  for (const auto &cell : mesh->active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == 5)
          for (const unsigned int v : face->vertex_indices())
            {
              const Point<dim> &p = face->vertex(v);
              distance
                = std::max(distance,
                           std::abs(std::hypot(p[0] - 1, p[1] - 0.5) - 0.2));
            }
  return Utilities::MPI::max(distance, MPI_COMM_WORLD);
}



template <int dim>
void
check(const std::string &mesh_file, const std::string &curved)
{
  const double on_curve = distance_from_hole<dim>(mesh_file, curved);
  const double polygon  = distance_from_hole<dim>(mesh_file, "");
  std::printf("%s, '%s': the hole's vertices on the surface to 1e-14: %s; "
              "without the entry off it by more than 1e-4: %s (%.1e)\n",
              mesh_file.c_str(),
              curved.c_str(),
              on_curve < 1e-14 ? "yes" : "NO",
              polygon > 1e-4 ? "yes" : "NO",
              polygon);
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);
  check<2>("meshes/plate_with_hole.msh", "5: sphere(1, 0.5)");
  check<2>("meshes/plate_with_hole_triangles.msh", "5: sphere(1, 0.5)");
  check<3>("meshes/block_with_hole.msh", "5: cylinder(1, 0.5, 0, 0, 0, 1)");
  check<3>("meshes/block_with_hole_tets.msh",
           "5: cylinder(1, 0.5, 0, 0, 0, 1)");
  try
    {
      distance_from_hole<2>("meshes/plate_with_hole.msh", "7: sphere(1, 0.5)");
      std::printf("an id the mesh does not have: NOT refused\n");
    }
  catch (const std::exception &e)
    {
      const std::string message = e.what();
      std::printf("an id the mesh does not have: refused naming the entry: "
                  "%s\n",
                  message.find("Geometry/Curved boundaries")
                      != std::string::npos ?
                    "yes" :
                    "NO");
    }
}
