// Checks the two limits of Tresca friction on the paper scene, in 2D
// (8 x 8 cells) and on the cube in 3D (4 x 4 x 4 cells, where the friction
// law is the ball |sigma_tau| <= g), 4 steps, no damage so the body is
// elastic:
// - g -> 0: with g = 1e-9 every contact node slips and the result equals
//   frictionless sliding (g = 0, where no active set is run) up to O(g);
//   the tangential traction is at most g.
// - g -> infinity: with g = 1e12 every node sticks and the result equals a
//   bottom clamped in both directions (the body starts at u = 0, so sticking
//   from the start is the same as u = 0 on the bottom).
// The test prints the largest relative difference of u_max, von_mises_max
// and elastic_energy over all steps between the paired runs.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "scene_runner.h"

using namespace VPContact;

// The statistics table of a run of the paper scene with @p friction_bound
// (empty: no contact, bottom clamped), as rows of named values.
template <int dim>
std::vector<std::map<std::string, double>>
run(const std::string &friction_bound)
{
  ParameterHandler prm;
  Simulator<dim>::declare_parameters(prm);
  prm.parse_input(dim == 2 ? SOURCE_DIR "/../../prm/paper_fig1.prm" :
                             SOURCE_DIR "/../../prm/paper_fig1_3d.prm");
  prm.enter_subsection("Geometry");
  prm.set("Subdivisions", dim == 2 ? "8, 8" : "4, 4, 4");
  prm.leave_subsection();
  prm.enter_subsection("Damage");
  prm.set("Model", "none");
  prm.leave_subsection();
  prm.enter_subsection("Time");
  prm.set("End time", "0.04");
  prm.leave_subsection();
  prm.enter_subsection("Solver");
  prm.set("Relative tolerance", "1e-12");
  prm.leave_subsection();
  prm.enter_subsection("Boundary conditions");
  if (friction_bound.empty())
    {
      prm.set("Clamped boundary ids", dim == 2 ? "0, 2" : "0, 4");
      prm.set("Contact boundary ids", "");
    }
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  prm.set("Friction bound", friction_bound.empty() ? "0" : friction_bound);
  prm.leave_subsection();
  prm.enter_subsection("Output");
  prm.set("Directory", "run");
  prm.set("Output every", "0");
  prm.leave_subsection();
  run_quietly<dim>(prm, ".");
  const auto rows = read_statistics("run/statistics.csv");
  return rows;
}

double
largest_difference(const std::vector<std::map<std::string, double>> &a,
                   const std::vector<std::map<std::string, double>> &b)
{
  double difference = 0;
  for (unsigned int n = 1; n < a.size(); ++n)
    for (const std::string column :
         {"u_max", "von_mises_max", "elastic_energy"})
      difference = std::max(difference,
                            std::abs(a[n].at(column) - b[n].at(column))
                              / std::abs(b[n].at(column)));
  return difference;
}

template <int dim>
void
check_limits()
{
  std::printf("%dD:\n", dim);
  const auto frictionless = run<dim>("0");
  const auto tiny         = run<dim>("1e-9");
  const auto huge         = run<dim>("1e12");
  const auto clamped      = run<dim>("");

  std::printf("g = 1e-9: stick/slip at the last step %g/%g, largest "
              "|sigma_tau|/g %.3f\n",
              tiny.back().at("stick_nodes"),
              tiny.back().at("slip_nodes"),
              tiny.back().at("friction_utilisation"));
  const double d_small = largest_difference(tiny, frictionless);
  std::printf("g = 1e-9 vs frictionless: largest relative difference "
              "%s (below 1e-6: %s)\n",
              d_small < 1e-6 ? "< 1e-6" : "large",
              d_small < 1e-6 ? "yes" : "NO");
  std::printf("g = 1e12: stick/slip at the last step %g/%g\n",
              huge.back().at("stick_nodes"),
              huge.back().at("slip_nodes"));
  const double d_large = largest_difference(huge, clamped);
  std::printf("g = 1e12 vs bottom clamped: largest relative difference "
              "%s (below 1e-8: %s)\n",
              d_large < 1e-8 ? "< 1e-8" : "large",
              d_large < 1e-8 ? "yes" : "NO");
  const double d_regimes = largest_difference(huge, frictionless);
  std::printf("stick vs frictionless differ (the test can tell them apart): "
              "%s\n",
              d_regimes > 1e-3 ? "yes" : "NO");
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_limits<2>();
  check_limits<3>();
}
