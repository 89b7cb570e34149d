// The convergence study of the paper scene, small: a reference run (64 x 64
// cells from the 4 x 4 coarse mesh, k = 0.00625) writes snapshots, then three
// uniform cycles (4 x 4 to 16 x 16, k = 0.1 to 0.025, h and k halved
// together) are compared with it at every common time. The test prints the
// convergence table written by the program and checks that the summed error
// of Theorem 2 decreases with an observed order of at least 0.5 between each
// pair of levels: the theorem's order is 1 for regular solutions, and the
// clamped-free corner of this scene limits uniform meshes to about 0.55 to
// 0.7 (doc/convergence.md); an order below 0.5 means the scheme or the error
// computation is broken.
//
// It also checks the a posteriori error estimate of every run (ErrorEstimator)
// against these errors: its effectivity index (estimate / error) must lie in
// [0.5, 2] on every level, and its observed order must differ from the
// error's by at most 0.2 between each pair of levels.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdio>

#include "scene_runner.h"

using namespace VPContact;

namespace
{
  void
  paper_scene_on_coarse_mesh(ParameterHandler &prm)
  {
    Simulator<2>::declare_parameters(prm);
    prm.parse_input(SOURCE_DIR "/../../prm/paper_fig1.prm");
    set_entry(prm, "Geometry", "Subdivisions", "4, 4");
    set_entry(prm,
              "Initial state",
              "Displacement and stress",
              "elastic equilibrium");
    set_entry(prm, "Output", "Output every", "0");
    // The adaptive cycles refine by the indicators of every step.
    set_entry(prm, "Error estimate", "Every steps", "1");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    ParameterHandler prm;
    paper_scene_on_coarse_mesh(prm);
    set_entry(prm, "Geometry", "Global refinements", "4");
    set_entry(prm, "Time", "Time step", "0.00625");
    set_entry(prm, "Reference solution", "Write snapshots", "true");
    set_entry(prm, "Reference solution", "Snapshot interval", "0.1");
    set_entry(prm, "Output", "Directory", "reference");
    run_quietly<2>(prm, SOURCE_DIR "/../../prm");
  }
  {
    ParameterHandler prm;
    paper_scene_on_coarse_mesh(prm);
    set_entry(prm, "Time", "Time step", "0.1");
    set_entry(prm, "Mesh refinement", "Number of cycles", "3");
    set_entry(prm, "Reference solution", "Compare with", "reference/reference");
    set_entry(prm, "Output", "Directory", "study");
    run_quietly<2>(prm, SOURCE_DIR "/../../prm");
  }

  MPI_Barrier(MPI_COMM_WORLD);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return 0;
  const auto rows = read_statistics("study/convergence.csv");
  for (const auto &row : rows)
    {
      std::printf("cells %5.0f  k %.4f  times %2.0f  e_u %.4e  e_sigma %.4e  "
                  "e_zeta %.4e  sum %.4e",
                  row.at("cells"),
                  row.at("k"),
                  row.at("compared_times"),
                  row.at("error_u"),
                  row.at("error_stress"),
                  row.at("error_damage"),
                  row.at("error_sum"));
      if (row.at("cycle") > 0)
        std::printf("  order %.2f  at least 0.5: %s",
                    row.at("error_sum_order"),
                    row.at("error_sum_order") >= 0.5 ? "yes" : "NO");
      const double effectivity = row.at("effectivity");
      std::printf("\n    estimate %.4e (space %.4e, time %.4e)  effectivity "
                  "%.2f  in [0.5, 2]: %s",
                  row.at("estimate"),
                  row.at("estimate_space"),
                  row.at("estimate_time"),
                  effectivity,
                  effectivity >= 0.5 && effectivity <= 2. ? "yes" : "NO");
      if (row.at("cycle") > 0)
        {
          const double difference
            = std::abs(row.at("estimate_order") - row.at("error_sum_order"));
          std::printf("  order %.2f  within 0.2 of the error's: %s",
                      row.at("estimate_order"),
                      difference <= 0.2 ? "yes" : "NO");
        }
      std::printf("\n");
    }
}
