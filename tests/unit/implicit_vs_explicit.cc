// Checks the implicit (backward Euler) viscoplastic step against the
// explicit one and the exact solution on the Maxwell relaxation scene
// (uniform stress sigma(t) = E e0 exp(-t/eta), eta = 0.1):
// - where both are stable, the two differ by O(k): the largest difference
//   over the steps halves with k (orders near 1);
// - the implicit error against exp(-t/eta) is O(k) too;
// - the fast-relaxation case eta = 1e-4, k = 0.01 (k = 100 eta, which the
//   explicit step refuses) runs to the end with the implicit step, and its
//   stress stays bounded (the backward Euler factor 1/(1 + k/eta) = 1/101).
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "scene_runner.h"

using namespace VPContact;

// The uniform stress sigma_xx(t_n) = von_mises_max of every step.
std::vector<double>
stress_history(const double k, const double eta, const std::string &integration)
{
  ParameterHandler prm;
  Simulator<2>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/maxwell_relaxation.prm");
  prm.enter_subsection("Viscoplasticity");
  prm.set("Relaxation time", eta);
  prm.set("Time integration", integration);
  prm.leave_subsection();
  prm.enter_subsection("Time");
  prm.set("Time step", k);
  prm.leave_subsection();
  prm.enter_subsection("Output");
  prm.set("Directory", "run");
  prm.set("Output every", "0");
  prm.leave_subsection();
  prm.enter_subsection("Verification");
  prm.set("Exact stress", "");
  prm.leave_subsection();
  run_quietly<2>(prm, SOURCE_DIR "/../../prm");
  std::vector<double> stress;
  for (const auto &row : read_statistics("run/statistics.csv"))
    stress.push_back(row.at("von_mises_max"));
  return stress;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     E = 1000, e0 = 1e-3, eta = 0.1;
  double                           previous_difference = 0, previous_error = 0;
  for (const double k : {0.02, 0.01, 0.005, 0.0025})
    {
      const auto explicit_stress = stress_history(k, eta, "explicit");
      const auto implicit_stress = stress_history(k, eta, "implicit");
      double     difference = 0, error = 0;
      for (unsigned int n = 1; n < implicit_stress.size(); ++n)
        {
          difference
            = std::max(difference,
                       std::abs(implicit_stress[n] - explicit_stress[n]));
          error = std::max(
            error,
            std::abs(implicit_stress[n]
                     - E * e0 * std::exp(-static_cast<double>(n) * k / eta)));
        }
      std::printf("k = %-7g max|implicit - explicit| = %.3e", k, difference);
      if (previous_difference > 0)
        std::printf(" (order %.2f)",
                    std::log2(previous_difference / difference));
      std::printf("  implicit error = %.3e", error);
      if (previous_error > 0)
        std::printf(" (order %.2f)", std::log2(previous_error / error));
      std::printf("\n");
      previous_difference = difference;
      previous_error      = error;
    }

  const auto fast    = stress_history(0.01, 1e-4, "implicit");
  double     largest = 0;
  for (const double s : fast)
    largest = std::max(largest, std::isfinite(s) ? s : 1e300);
  std::printf("fast relaxation (eta = 1e-4, k = 0.01, implicit): %zu steps, "
              "sigma_1 = %.6f (E e0 / 101 = %.6f), largest %.6f, last "
              "below 1e-90 (1/101^50 = 6.1e-101): %s\n",
              fast.size() - 1,
              fast[1],
              E * e0 / 101.,
              largest,
              fast.back() < 1e-90 ? "yes" : "no");
}
