// Checks the order of the explicit scheme in time on the Maxwell relaxation
// scene (uniform stress, strain held fixed after the first step): the
// largest stress error against the exact solution E e0 exp(-t/eta) over all
// steps, for k = 0.02, 0.01, 0.005, 0.0025, decays at order 1 (the paper's
// O(h + k) with h playing no role in a uniform state). The test prints the
// errors, the observed orders log2(e_k / e_{k/2}) and whether each lies in
// [0.9, 1.1]; a scheme of another order prints "no" and fails the diff.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "scene_runner.h"

using namespace VPContact;

double
largest_stress_error(const double k)
{
  ParameterHandler prm;
  Simulator<2>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/maxwell_relaxation.prm");
  prm.enter_subsection("Time");
  prm.set("Time step", k);
  prm.leave_subsection();
  prm.enter_subsection("Output");
  prm.set("Directory", "run");
  prm.set("Output every", "0");
  prm.leave_subsection();
  prm.enter_subsection("Verification");
  prm.set("Exact stress", "t < k/2 ? 0 : E*e0*exp(-t/eta); 0; 0");
  prm.set("Function constants",
          "E:1000, e0:0.001, eta:0.1, k:" + std::to_string(k));
  prm.leave_subsection();

  run_quietly<2>(prm, SOURCE_DIR "/../../prm");

  // max over the steps of the column stress_error_max.
  double error = 0;
  for (const auto &row : read_statistics("run/statistics.csv"))
    error = std::max(error, row.at("stress_error_max"));
  return error;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  double                           previous = 0;
  for (const double k : {0.02, 0.01, 0.005, 0.0025})
    {
      const double error = largest_stress_error(k);
      std::printf("k = %-7g max_n |sigma_n - sigma(t_n)| = %.3e", k, error);
      if (previous > 0)
        {
          const double order = std::log2(previous / error);
          std::printf("  order %.2f  in [0.9, 1.1]: %s",
                      order,
                      (order >= 0.9 && order <= 1.1) ? "yes" : "no");
        }
      std::printf("\n");
      previous = error;
    }
}
