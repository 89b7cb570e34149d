// The simulator's comparisons of a step with the exact solution of a
// verification scene: the errors of the displacement, the stress and the
// damage as statistics columns and screen text.
#include <vpcontact/input/input_error.h>
#include <vpcontact/simulator/simulator.h>

#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::add_verification_statistics(
    std::string                       &line,
    const double                       time,
    const double                       u_max,
    const std::vector<Vector<double>> &components)
  {
    // The errors against the closed forms of the Verification section.
    if (verification.is_active())
      {
        const auto errors
          = verification.compute_errors(dof_handler,
                                        displacement_problem.ghosted_solution(),
                                        time,
                                        u_max);
        // The exact solution is evaluated at every quadrature point: one
        // NaN there makes the L2 error NaN (a maximum would pass it by).
        AssertThrow(std::isfinite(errors.l2) && std::isfinite(errors.max_nodal),
                    ExcMessage("Verification/Exact displacement is not finite "
                               "(NaN or infinity) somewhere at t = "
                               + to_text(time)
                               + ". Check it for divisions by zero, roots "
                                 "or logarithms of negative numbers."));
        statistics.add_value("u_error_max_nodal", errors.max_nodal);
        statistics.add_value("u_error_L2", errors.l2);
        // Errors are round-off in verification scenes: printed with two
        // digits, they differ between runs only below numdiff's absolute
        // tolerance.
        line += "  error: nodal max = " + printf_text("%.2e", errors.max_nodal)
                + ", L2 = " + printf_text("%.2e", errors.l2);
      }
    if (verification.has_exact_stress())
      {
        const double error = stress_error(time);
        // The scale of the stress for the relative error in the summary.
        double stress_scale = 0;
        for (const auto &c : components)
          stress_scale = std::max(stress_scale, c.linfty_norm());
        verification.record_stress_error(error,
                                         Utilities::MPI::max(stress_scale,
                                                             mpi_communicator));
        AssertThrow(std::isfinite(error),
                    ExcMessage("Verification/Exact stress is not finite (NaN "
                               "or infinity) somewhere at t = "
                               + to_text(time) + "."));
        statistics.add_value("stress_error_max", error);
        line += "  stress error = " + printf_text("%.2e", error);
      }
    if (verification.has_exact_damage())
      {
        const double error
          = verification.damage_error(dof_handler,
                                      displacement_problem.ghosted_solution(),
                                      time);
        AssertThrow(std::isfinite(error),
                    ExcMessage("Verification/Exact damage is not finite (NaN "
                               "or infinity) somewhere at t = "
                               + to_text(time) + "."));
        statistics.add_value("damage_error_max", error);
        line += "  damage error = " + printf_text("%.2e", error);
      }
  }



  template <int dim>
  double
  Simulator<dim>::stress_error(const double time) const
  {
    // max over quadrature points of |sigma_h - sigma| (Frobenius norm).
    FEValues<dim> fe_values(discretization.mapping(),
                            discretization.finite_element(),
                            discretization.quadrature(),
                            update_quadrature_points);
    double        error = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          const auto history = displacement_problem.history().get_data(cell);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const double e
                = (history[q].stress
                   - verification.exact_stress(fe_values.quadrature_point(q),
                                               time))
                    .norm();
              // std::max() would pass a NaN by: it counts as infinite.
              error = std::max(error,
                               std::isfinite(e) ?
                                 e :
                                 std::numeric_limits<double>::infinity());
            }
        }
    return Utilities::MPI::max(error, mpi_communicator);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
