// Checks that resuming is exact for the kinds of scene that the paper scene
// of checkpoint_resume does not have: the implicit viscoplastic step with a
// prescribed displacement (its first Newton correction starts from the
// constraints of the previous step, so these are part of the state), damage
// under a prescribed displacement, a 3D scene, a Gmsh mesh with a global
// refinement, and an elastic initial equilibrium. Each scene runs with a
// checkpoint after every step; then its newest checkpoint is dropped and the
// run resumed from the one before, which must give the same statistics.csv
// to the last digit (the wall time aside).
#include <vpcontact/app/mpi_io_choice.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <regex>

#include "checkpoint_runner.h"

using namespace VPContact;

namespace
{
  template <int dim>
  void
  check(const std::string &name,
        const std::string &scene,
        const std::string &changes)
  {
    const auto parameters = [&](ParameterHandler &prm, const bool resume) {
      Simulator<dim>::declare_parameters(prm);
      prm.parse_input(scene);
      prm.parse_input_from_string(changes);
      prm.enter_subsection("Output");
      prm.set("Directory", name);
      prm.set("Output every", "0");
      prm.set("Deterministic screen output", true);
      prm.leave_subsection();
      prm.enter_subsection("Checkpoint");
      prm.set("Every steps", "1");
      prm.set("Resume from checkpoint", resume);
      prm.leave_subsection();
    };
    ParameterHandler first;
    parameters(first, false);
    run_logged<dim>(first, MPI_COMM_WORLD, name + ".log");
    const auto uninterrupted = read_lines(name + "/statistics.csv");

    std::filesystem::remove_all(name + "/checkpoint");
    std::filesystem::rename(name + "/checkpoint.old", name + "/checkpoint");
    ParameterHandler second;
    parameters(second, true);
    run_logged<dim>(second, MPI_COMM_WORLD, name + ".resumed.log");
    const auto resumed = read_lines(name + "/statistics.csv");

    // The wall time is the sixth column.
    const std::regex wall_time("^((?:[^,]*,){5})[^,]*");
    bool             identical = (uninterrupted.size() == resumed.size());
    for (unsigned int r = 0; identical && r < resumed.size(); ++r)
      identical = (std::regex_replace(uninterrupted[r], wall_time, "$1")
                   == std::regex_replace(resumed[r], wall_time, "$1"));
    std::cout << name << ": resumed at step " << uninterrupted.size() - 3
              << " of " << uninterrupted.size() - 2
              << ", statistics.csv identical: " << (identical ? "yes" : "NO")
              << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  // MPI-IO as the program chooses it (mpi_io_choice.h).
  VPContact::prefer_romio_for_mpi_io();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                prm = SOURCE_DIR "/../../prm/";

  check<2>("implicit_prescribed",
           prm + "stiff/fast_relaxation_implicit.prm",
           "subsection Time\n set End time = 0.05\nend");
  check<2>("damage_prescribed",
           prm + "damage_ode.prm",
           "subsection Time\n set End time = 0.3\nend");
  check<3>("bar_3d", SOURCE_DIR "/../app/elastic_bar_3d.prm", "");
  check<2>("gmsh_refined",
           prm + "l_shape_gmsh.prm",
           "subsection Time\n set End time = 0.75\nend");
  check<2>("elastic_equilibrium",
           prm + "paper_fig1.prm",
           "subsection Geometry\n set Subdivisions = 8, 8\nend\n"
           "subsection Damage\n set Model = none\nend\n"
           "subsection Initial state\n"
           " set Displacement and stress = elastic equilibrium\nend\n"
           "subsection Time\n set End time = 0.03\nend");
}
