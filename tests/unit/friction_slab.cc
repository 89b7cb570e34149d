// Checks 3D Tresca friction against 2D: a slab (0,1) x (0,1/8) x (0,1), one
// cell thick in y with rollers (u_y = 0) on both y faces, is the 2D
// plane-strain slip scene (prm/paper_fig1_slip.prm, 8 x 8 cells, g = 20)
// extruded in y. Its discrete solution is the 2D one at every node, and its
// contact nodes are the 2D ones twice (at y = 0 and y = 1/8), each with
// the tangent line x: the same stick and slip sets, the same displacement
// and traction. The test runs both for 30 steps, while the slip zone grows,
// and prints the largest differences over the steps, of the statistics and
// of the displacement at four monitor points (2D (x, y) is 3D (x, y', y)).
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene_runner.h"

using namespace VPContact;

template <int dim>
std::vector<std::map<std::string, double>>
run()
{
  ParameterHandler prm;
  Simulator<dim>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/paper_fig1_slip.prm", "", true);
  set_entry(prm, "Time", "End time", "0.3");
  set_entry(prm, "Solver", "Relative tolerance", "1e-12");
  set_entry(prm, "Material", "Plane hypothesis", "plane strain");
  set_entry(prm, "Output", "Directory", "run");
  set_entry(prm, "Output", "Output every", "0");
  if (dim == 2)
    {
      set_entry(prm, "Geometry", "Subdivisions", "8, 8");
      set_entry(prm,
                "Output",
                "Monitor points",
                "1, 1; 0.5, 0; 1, 0; 0.5, 0.55");
    }
  else
    {
      set_entry(prm,
                "Output",
                "Monitor points",
                "1, 0.0625, 1; 0.5, 0, 0; 1, 0.125, 0; 0.5, 0.0625, 0.55");
      set_entry(prm, "Geometry", "Upper corner", "1, 0.125, 1");
      set_entry(prm, "Geometry", "Subdivisions", "8, 1, 8");
      set_entry(prm, "Boundary conditions", "Roller boundary ids", "2:y, 3:y");
      set_entry(prm, "Boundary conditions", "Contact boundary ids", "4");
      set_entry(prm, "Boundary conditions", "Traction", "55*exp(t); 0; 0");
    }
  run_quietly<dim>(prm, ".");
  return read_statistics("run/statistics.csv");
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       plane = run<2>();
  const auto                       slab  = run<3>();

  bool   same_sets = plane.size() == slab.size();
  double d_u = 0, d_utilisation = 0, d_energy = 0, violation = 0;
  double d_monitor = 0;
  for (unsigned int n = 1; same_sets && n < plane.size(); ++n)
    {
      same_sets = same_sets
                  && slab[n].at("stick_nodes") == 2 * plane[n].at("stick_nodes")
                  && slab[n].at("slip_nodes") == 2 * plane[n].at("slip_nodes");
      d_u           = std::max(d_u,
                     std::abs(slab[n].at("u_max") - plane[n].at("u_max"))
                       / plane[n].at("u_max"));
      d_utilisation = std::max(d_utilisation,
                               std::abs(slab[n].at("friction_utilisation")
                                        - plane[n].at("friction_utilisation")));
      d_energy      = std::max(d_energy,
                          std::abs(slab[n].at("elastic_energy") / 0.125
                                   - plane[n].at("elastic_energy"))
                            / plane[n].at("elastic_energy"));
      violation     = std::max(violation, slab[n].at("friction_violation"));
      for (const std::string point : {"1", "2", "3", "4"})
        {
          const auto       &u = plane[n], &v = slab[n];
          const std::string m = "monitor" + point + "_u";
          d_monitor
            = std::max({d_monitor,
                        std::abs(v.at(m + "x") - u.at(m + "x")) / u.at("u_max"),
                        std::abs(v.at(m + "z") - u.at(m + "y")) / u.at("u_max"),
                        std::abs(v.at(m + "y")) / u.at("u_max")});
        }
    }
  std::printf("2D stick/slip at steps 1, 15, 30: %g/%g, %g/%g, %g/%g\n",
              plane[1].at("stick_nodes"),
              plane[1].at("slip_nodes"),
              plane[15].at("stick_nodes"),
              plane[15].at("slip_nodes"),
              plane[30].at("stick_nodes"),
              plane[30].at("slip_nodes"));
  std::printf("slab stick/slip twice the 2D ones at every step: %s\n",
              same_sets ? "yes" : "NO");
  std::printf("largest relative difference of u_max below 1e-8: %s\n",
              d_u < 1e-8 ? "yes" : "NO");
  std::printf("largest difference of u at the monitor points, relative to "
              "u_max, below 1e-8: %s\n",
              d_monitor < 1e-8 ? "yes" : "NO");
  std::printf("largest difference of max|sigma_tau|/g below 1e-8: %s\n",
              d_utilisation < 1e-8 ? "yes" : "NO");
  std::printf("largest relative difference of the energy per width below "
              "1e-8: %s\n",
              d_energy < 1e-8 ? "yes" : "NO");
  std::printf("slab: largest violation of the Tresca conditions below 1e-8 "
              "of g: %s\n",
              violation < 1e-8 ? "yes" : "NO");
}
