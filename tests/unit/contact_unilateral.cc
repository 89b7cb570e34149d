// Checks unilateral contact against bilateral contact and the Signorini
// conditions where the body lifts off.
//
// (1) The slip scene (prm/paper_fig1_slip.prm, g = 20, 8 x 8 cells) with its
// top pressed down by 200 N/m^2: every contact node stays pressed, so the
// unilateral run must give the bilateral run's results (the same stick and
// slip sets, u_max and energy to solver tolerance) with no node separated.
// (2) The block of prm/block_lift.prm (Coulomb, mu = 0.5) on a coarser mesh:
// its right end lifts off; the separated nodes must carry no pressure and
// have a non-negative gap, the contact nodes a non-negative pressure and no
// gap, and Coulomb's law must hold at the contact nodes. The same output on
// 2 ranks.
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene_runner.h"

using namespace VPContact;

std::vector<std::map<std::string, double>>
run_pressed(const std::string &normal_condition)
{
  ParameterHandler prm;
  Simulator<2>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/paper_fig1_slip.prm", "", true);
  set_entry(prm, "Geometry", "Subdivisions", "8, 8");
  set_entry(prm, "Time", "End time", "0.3");
  set_entry(prm, "Solver", "Relative tolerance", "1e-12");
  set_entry(prm, "Boundary conditions", "Traction boundary ids", "1, 3");
  set_entry(prm,
            "Boundary conditions",
            "Traction",
            "(x > 1 - 1e-9 ? 55*exp(t) : 0); (y > 1 - 1e-9 ? -200 : 0)");
  set_entry(prm, "Contact", "Normal condition", normal_condition);
  set_entry(prm, "Output", "Directory", "run_" + normal_condition);
  set_entry(prm, "Output", "Output every", "0");
  run_quietly<2>(prm, ".");
  return read_statistics("run_" + normal_condition + "/statistics.csv");
}



std::vector<std::map<std::string, double>>
run_lift()
{
  ParameterHandler prm;
  Simulator<2>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/block_lift.prm", "", true);
  set_entry(prm, "Geometry", "Subdivisions", "16, 4");
  set_entry(prm, "Output", "Directory", "run_lift");
  set_entry(prm, "Output", "Output every", "0");
  run_quietly<2>(prm, ".");
  return read_statistics("run_lift/statistics.csv");
}



void
check_pressed()
{
  const auto bilateral  = run_pressed("bilateral");
  const auto unilateral = run_pressed("unilateral");
  bool       same_sets  = bilateral.size() == unilateral.size();
  double     d_u = 0, d_energy = 0, separated = 0;
  for (unsigned int n = 1; same_sets && n < bilateral.size(); ++n)
    {
      const auto &b = bilateral[n], &u = unilateral[n];
      same_sets = same_sets && b.at("stick_nodes") == u.at("stick_nodes")
                  && b.at("slip_nodes") == u.at("slip_nodes");
      d_u = std::max(d_u,
                     std::abs(u.at("u_max") - b.at("u_max")) / b.at("u_max"));
      d_energy
        = std::max(d_energy,
                   std::abs(u.at("elastic_energy") - b.at("elastic_energy"))
                     / b.at("elastic_energy"));
      separated = std::max(separated, u.at("separated_nodes"));
    }
  const auto &last = unilateral.back();
  std::printf("pressed: stick/slip at the last step: %g/%g\n",
              last.at("stick_nodes"),
              last.at("slip_nodes"));
  std::printf("pressed: no node separated at any step: %s\n",
              separated == 0 ? "yes" : "NO");
  std::printf("pressed: the bilateral run's stick and slip sets at every "
              "step: %s\n",
              same_sets ? "yes" : "NO");
  std::printf("pressed: largest relative difference of u_max below 1e-9: %s\n",
              d_u < 1e-9 ? "yes" : "NO");
  std::printf("pressed: largest relative difference of the energy below "
              "1e-9: %s\n",
              d_energy < 1e-9 ? "yes" : "NO");
}



void
check_lift()
{
  const auto rows     = run_lift();
  double     pressure = 0, gap = 0, friction = 0;
  for (unsigned int n = 1; n < rows.size(); ++n)
    {
      pressure = std::max(pressure, rows[n].at("pressure_violation"));
      gap      = std::max(gap, rows[n].at("gap_violation"));
      friction = std::max(friction, rows[n].at("friction_violation"));
    }
  const auto &last = rows.back();
  std::printf("lift: contact/separated nodes at t = 1: %g/%g, stick/slip "
              "%g/%g\n",
              last.at("contact_nodes"),
              last.at("separated_nodes"),
              last.at("stick_nodes"),
              last.at("slip_nodes"));
  std::printf("lift: the right end separates (more than 4 nodes "
              "separated): %s\n",
              last.at("separated_nodes") > 4 ? "yes" : "NO");
  std::printf("lift: largest violation of the pressure conditions below "
              "1e-8 of the stress scale: %s\n",
              pressure < 1e-8 ? "yes" : "NO");
  std::printf("lift: largest violation of the gap conditions below 1e-12 "
              "m: %s\n",
              gap < 1e-12 ? "yes" : "NO");
  std::printf("lift: largest violation of Coulomb's law below 1e-8: %s\n",
              friction < 1e-8 ? "yes" : "NO");
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Every rank checks; rank 0 prints.
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);
  check_pressed();
  check_lift();
}
