// Errors against a closed-form displacement (section "Verification").
#include <vpcontact/parsed_function.h>
#include <vpcontact/verification.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cstdio>

namespace VPContact
{
  template <int dim>
  void
  Verification<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    {
      prm.declare_entry("Exact displacement",
                        "",
                        Patterns::Anything(),
                        "If not empty: the exact displacement u(x, t) [m], "
                        "one expression per component separated by ';', in "
                        "x, y (z) and t. Its nodal and L2 errors are then "
                        "printed and written to statistics.csv.");
      prm.declare_entry("Exact stress",
                        "",
                        Patterns::Anything(),
                        "If not empty: the exact stress sigma(x, t) [Pa], its "
                        "independent components separated by ';' in the "
                        "order xx; yy; xy (3D: xx; yy; zz; xy; xz; yz). The "
                        "largest error over the quadrature points is then "
                        "printed and written to statistics.csv.");
      prm.declare_entry("Function constants",
                        "",
                        Patterns::Map(Patterns::Anything(), Patterns::Double()),
                        "Named constants for 'Exact displacement', as "
                        "name:value pairs.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Verification<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Verification");
    if (!prm.get("Exact displacement").empty())
      {
        const auto constants
          = parse_function_constants(prm, "Function constants");
        exact_displacement = parse_function_entry<dim>(prm,
                                                       "Verification",
                                                       "Exact displacement",
                                                       dim,
                                                       constants);
      }
    else
      exact_displacement.reset();
    if (!prm.get("Exact stress").empty())
      {
        const auto constants
          = parse_function_constants(prm, "Function constants");
        exact_stress_function = parse_function_entry<dim>(
          prm,
          "Verification",
          "Exact stress",
          SymmetricTensor<2, dim>::n_independent_components,
          constants);
      }
    else
      exact_stress_function.reset();
    prm.leave_subsection();
  }



  template <int dim>
  bool
  Verification<dim>::is_active() const
  {
    return exact_displacement != nullptr;
  }



  template <int dim>
  bool
  Verification<dim>::has_exact_stress() const
  {
    return exact_stress_function != nullptr;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Verification<dim>::exact_stress(const Point<dim> &point,
                                  const double      time) const
  {
    exact_stress_function->set_time(time);
    SymmetricTensor<2, dim> sigma;
    for (unsigned int c = 0;
         c < SymmetricTensor<2, dim>::n_independent_components;
         ++c)
      sigma.access_raw_entry(c) = exact_stress_function->value(point, c);
    return sigma;
  }



  template <int dim>
  void
  Verification<dim>::record_stress_error(const double error,
                                         const double stress_scale)
  {
    max_stress_error = std::max(max_stress_error, error);
    max_stress       = std::max(max_stress, stress_scale);
  }



  template <int dim>
  typename Verification<dim>::Errors
  Verification<dim>::compute_errors(
    const DoFHandler<dim>               &dof_handler,
    const TrilinosWrappers::MPI::Vector &solution,
    const double                         time,
    const double                         u_max)
  {
    Assert(is_active(), ExcInternalError());
    exact_displacement->set_time(time);

    Errors                        errors;
    TrilinosWrappers::MPI::Vector nodal(dof_handler.locally_owned_dofs(),
                                        solution.get_mpi_communicator());
    VectorTools::interpolate(dof_handler, *exact_displacement, nodal);
    TrilinosWrappers::MPI::Vector owned(nodal);
    owned = solution; // imports the locally owned part of the ghosted vector
    nodal -= owned;
    errors.max_nodal = nodal.linfty_norm();

    Vector<float> cellwise(dof_handler.get_triangulation().n_active_cells());
    VectorTools::integrate_difference(dof_handler,
                                      solution,
                                      *exact_displacement,
                                      cellwise,
                                      QGauss<dim>(3),
                                      VectorTools::L2_norm);
    errors.l2
      = VectorTools::compute_global_error(dof_handler.get_triangulation(),
                                          cellwise,
                                          VectorTools::L2_norm);
    max_nodal_error  = std::max(max_nodal_error, errors.max_nodal);
    max_displacement = std::max(max_displacement, u_max);
    return errors;
  }



  template <int dim>
  std::string
  Verification<dim>::summary() const
  {
    const auto line
      = [](const char *what, const double error, const double scale) {
          const double relative = (scale > 0 ? error / scale : error);
          char         buffer[200];
          std::snprintf(buffer,
                        sizeof(buffer),
                        "Verification: largest %s error / largest %s = %.1e "
                        "(round-off, below %.0e: %s)\n",
                        what,
                        what,
                        relative,
                        round_off_level,
                        relative < round_off_level ? "yes" : "NO");
          return std::string(buffer);
        };
    std::string text;
    if (is_active())
      text += line("nodal displacement", max_nodal_error, max_displacement);
    if (has_exact_stress())
      text += line("stress", max_stress_error, max_stress);
    return text;
  }



  template class Verification<2>;
  template class Verification<3>;
} // namespace VPContact
