// Checks that Coulomb's law gives Tresca's results where mu |sigma_nu| equals
// Tresca's bound g at every contact node.
//
// The pressed slip scene of contact_unilateral (prm/paper_fig1_slip.prm,
// g = 20, 8 x 8 cells, its top pressed down by 200 N/m^2, unilateral
// contact, three steps of 0.1) runs with Tresca's law to each step's time;
// the contact pressure p_i its last step leaves at each contact node gives
// mu_i = g / p_i. Coulomb's law with mu(x, t) equal to mu_i at node i and
// step n must then find the Tresca run's sets, displacement, energy and
// friction force in every step: at its solution the bounds mu_i p_i are g.
// The same output on 2 ranks.
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene_runner.h"

using namespace VPContact;

constexpr double       friction_bound = 20;
constexpr double       time_step      = 0.1;
constexpr unsigned int n_steps        = 3;

void
pressed_scene(ParameterHandler  &prm,
              const double       end_time,
              const std::string &folder)
{
  Simulator<2>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/paper_fig1_slip.prm", "", true);
  set_entry(prm, "Geometry", "Subdivisions", "8, 8");
  set_entry(prm, "Time", "End time", Utilities::to_string(end_time));
  set_entry(prm, "Time", "Time step", Utilities::to_string(time_step));
  set_entry(prm, "Solver", "Relative tolerance", "1e-12");
  set_entry(prm, "Boundary conditions", "Traction boundary ids", "1, 3");
  set_entry(prm,
            "Boundary conditions",
            "Traction",
            "(x > 1 - 1e-9 ? 55*exp(t) : 0); (y > 1 - 1e-9 ? -200 : 0)");
  set_entry(prm, "Contact", "Normal condition", "unilateral");
  set_entry(prm, "Output", "Directory", folder);
  set_entry(prm, "Output", "Output every", "0");
}



// The (x, p) of every contact node (y = 0 and x > 0: the corner at x = 0 is
// clamped) at the end of a Tresca run to
// @p end_time, sorted by x, on every rank.
std::vector<std::pair<double, double>>
tresca_pressures(const double end_time)
{
  ParameterHandler prm;
  pressed_scene(prm, end_time, "run_tresca");
  std::vector<std::pair<double, double>> owned;
  {
    std::ofstream   log("screen.log");
    std::streambuf *old = std::cout.rdbuf(log.rdbuf());
    Simulator<2>    simulator(prm, ".", MPI_COMM_WORLD);
    simulator.run();
    std::cout.rdbuf(old);

    const SimulatorAccess<2> access = simulator.access();
    OwnedLayout              layout;
    layout.reinit(access.locally_owned_dofs, MPI_COMM_WORLD);
    const auto fields
      = simulator.displacement().contact()->output_fields(layout);
    // The contact pressure is the field of component 0 of the third one.
    const LA::MPI::Vector                      &pressure = fields.at(2).values;
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(access.mapping,
                                         access.dof_handler,
                                         points);
    const auto x_dofs
      = DoFTools::extract_dofs(access.dof_handler,
                               access.fe.component_mask(
                                 FEValuesExtractors::Scalar(0)));
    for (const auto &[dof, point] : points)
      if (x_dofs.is_element(dof) && access.locally_owned_dofs.is_element(dof)
          && std::abs(point[1]) < 1e-12 && point[0] > 1e-12)
        owned.emplace_back(point[0], pressure(dof));
  }
  std::vector<std::pair<double, double>> all;
  for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, owned))
    all.insert(all.end(), part.begin(), part.end());
  std::sort(all.begin(), all.end());
  return all;
}



// mu(x, t) = g / p_i(t_n) at node i and step n, as nested conditions in x
// and t (midway between nodes and between step times).
std::string
coefficient_expression(
  const std::vector<std::vector<std::pair<double, double>>> &steps)
{
  auto number = [](const double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.17g", v);
    return std::string(text);
  };
  std::string expression;
  for (unsigned int n = 0; n < steps.size(); ++n)
    {
      const auto &nodes = steps[n];
      std::string in_x  = number(friction_bound / nodes.back().second);
      // Below the first contact node: the clamped corner, no contact.
      for (unsigned int i = nodes.size() - 1; i-- > 0;)
        in_x = "(x < " + number(0.5 * (nodes[i].first + nodes[i + 1].first))
               + " ? " + number(friction_bound / nodes[i].second) + " : " + in_x
               + ")";
      in_x = "(x < " + number(0.5 * nodes[0].first) + " ? 0 : " + in_x + ")";
      expression
        += (n + 1 < steps.size() ?
              "(t < " + number((n + 1.5) * time_step) + " ? " + in_x + " : " :
              in_x);
    }
  return expression + std::string(steps.size() - 1, ')');
}



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Every rank checks; rank 0 prints.
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);

  // The Tresca runs to each step's time; the last one's statistics are
  // the Tresca run's.
  std::vector<std::vector<std::pair<double, double>>> steps;
  double                                              p_min = 1e300;
  for (unsigned int n = 1; n <= n_steps; ++n)
    {
      steps.push_back(tresca_pressures(n * time_step));
      for (const auto &[x, p] : steps.back())
        p_min = std::min(p_min, p);
    }
  const auto tresca = read_statistics("run_tresca/statistics.csv");
  std::printf("contact nodes: %u, every one pressed (p > 0): %s\n",
              static_cast<unsigned int>(steps.back().size()),
              p_min > 0 ? "yes" : "NO");

  ParameterHandler prm;
  pressed_scene(prm, n_steps * time_step, "run_coulomb");
  set_entry(prm, "Contact", "Friction law", "Coulomb");
  set_entry(prm,
            "Contact",
            "Friction coefficient",
            coefficient_expression(steps));
  run_quietly<2>(prm, ".");
  const auto coulomb = read_statistics("run_coulomb/statistics.csv");

  bool   same_sets = tresca.size() == coulomb.size();
  double d_u = 0, d_energy = 0, d_friction = 0;
  for (unsigned int n = 1; same_sets && n < tresca.size(); ++n)
    {
      const auto &t = tresca[n], &c = coulomb[n];
      same_sets = same_sets && t.at("stick_nodes") == c.at("stick_nodes")
                  && t.at("slip_nodes") == c.at("slip_nodes");
      auto relative = [&](const char *column) {
        return std::abs(c.at(column) - t.at(column)) / std::abs(t.at(column));
      };
      d_u        = std::max(d_u, relative("u_max"));
      d_energy   = std::max(d_energy, relative("elastic_energy"));
      d_friction = std::max(d_friction, relative("friction_force"));
    }
  const auto &last = coulomb.back();
  std::printf("steps: %u, stick/slip at the last step: %g/%g\n",
              static_cast<unsigned int>(coulomb.size() - 1),
              last.at("stick_nodes"),
              last.at("slip_nodes"));
  std::printf("Coulomb has the Tresca run's stick and slip sets at every "
              "step: %s\n",
              same_sets ? "yes" : "NO");
  std::printf("largest relative difference of u_max below 1e-8: %s\n",
              d_u < 1e-8 ? "yes" : "NO");
  std::printf("largest relative difference of the energy below 1e-8: %s\n",
              d_energy < 1e-8 ? "yes" : "NO");
  std::printf("largest relative difference of the friction force below "
              "1e-8: %s\n",
              d_friction < 1e-8 ? "yes" : "NO");
}
