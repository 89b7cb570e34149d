// Checks 3D Tresca friction on a contact face in general position: the slip
// scene (prm/paper_fig1_3d_slip.prm, g = 20) on a 4 x 4 x 4 cube, and the same
// cube and load rotated by 30 degrees about the axis (1, 2, 3). The rotated
// contact face has a normal with three non-zero components, so its normal
// constraint ties all three displacement components of a node and the
// tangent plane is read off two coefficients. Both meshes are written by
// GridOut as UCD files and read through Geometry/Mesh file. Tresca's law is
// invariant under rotations: the stick and slip sets, |u|max, the largest von
// Mises stress, the energy and the largest |sigma_tau|/g must agree at every
// step to the solver tolerance.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "scene_runner.h"

using namespace VPContact;

// The cube (0,1)^3 in 4^3 cells with the box's boundary ids, rotated by
// @p angle about @p axis, into @p file (rank 0).
void
write_cube(const std::string  &file,
           const Tensor<1, 3> &axis,
           const double        angle)
{
  Triangulation<3> cube;
  GridGenerator::subdivided_hyper_cube(cube, 4, 0., 1., true);
  if (angle != 0.)
    GridTools::rotate(axis, angle, cube);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::ofstream out(file);
      out.precision(17); // the rotated vertices to round-off
      GridOut grid_out;
      grid_out.set_flags(GridOutFlags::Ucd(false, true));
      grid_out.write_ucd(cube, out);
    }
  MPI_Barrier(MPI_COMM_WORLD);
}

std::vector<std::map<std::string, double>>
run(const std::string &mesh, const Tensor<1, 3> &traction_direction)
{
  ParameterHandler prm;
  Simulator<3>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/paper_fig1_3d_slip.prm", "", true);
  set_entry(prm, "Geometry", "Mesh", "file");
  set_entry(prm, "Geometry", "Mesh file", mesh);
  // A mesh file names every boundary id: the box's others are free.
  set_entry(prm, "Boundary conditions", "Free boundary ids", "2, 3, 5");
  set_entry(prm, "Time", "End time", "0.1");
  set_entry(prm, "Solver", "Relative tolerance", "1e-12");
  set_entry(prm, "Output", "Directory", "run");
  set_entry(prm, "Output", "Output every", "0");
  char traction[200];
  std::snprintf(traction,
                sizeof(traction),
                "55*exp(t)*%.17g; 55*exp(t)*%.17g; 55*exp(t)*%.17g",
                traction_direction[0],
                traction_direction[1],
                traction_direction[2]);
  set_entry(prm, "Boundary conditions", "Traction", traction);
  run_quietly<3>(prm, ".");
  return read_statistics("run/statistics.csv");
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Tensor<1, 3> axis  = Tensor<1, 3>({1., 2., 3.}) / std::sqrt(14.);
  const double       angle = M_PI / 6;
  write_cube("cube.inp", axis, 0.);
  write_cube("rotated.inp", axis, angle);

  // The traction (55 e^t, 0, 0) rotated with the body: e_x rotated.
  Triangulation<3> point;
  GridGenerator::hyper_cube(point, 0., 1.);
  GridTools::rotate(axis, angle, point);
  Tensor<1, 3> e_x
    = point.begin_active()->vertex(1) - point.begin_active()->vertex(0);

  const auto straight = run("cube.inp", Tensor<1, 3>({1., 0., 0.}));
  const auto rotated  = run("rotated.inp", e_x);

  bool   same_sets = straight.size() == rotated.size();
  double largest   = 0;
  for (unsigned int n = 1; same_sets && n < straight.size(); ++n)
    {
      same_sets
        = same_sets
          && straight[n].at("stick_nodes") == rotated[n].at("stick_nodes")
          && straight[n].at("slip_nodes") == rotated[n].at("slip_nodes");
      for (const std::string column :
           {"u_max", "von_mises_max", "elastic_energy", "friction_utilisation"})
        largest
          = std::max(largest,
                     std::abs(straight[n].at(column) - rotated[n].at(column))
                       / std::abs(straight[n].at(column)));
    }
  std::printf("stick/slip at steps 1 and 10: %g/%g, %g/%g\n",
              straight[1].at("stick_nodes"),
              straight[1].at("slip_nodes"),
              straight[10].at("stick_nodes"),
              straight[10].at("slip_nodes"));
  std::printf("rotated: the same stick and slip sets at every step: %s\n",
              same_sets ? "yes" : "NO");
  std::printf("rotated: u_max, von Mises max, energy and max|sigma_tau|/g "
              "agree to 1e-8: %s\n",
              largest < 1e-8 ? "yes" : "NO");
  std::printf("rotated: largest violation of the Tresca conditions below 1e-8 "
              "of g: %s\n",
              rotated.back().at("friction_violation") < 1e-8 ? "yes" : "NO");
}
