// Errors against a closed-form displacement (section "Verification").
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parsed_function.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/postprocess/verification.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
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
      prm.declare_entry("Exact damage",
                        "",
                        Patterns::Anything(),
                        "If not empty: the exact damage zeta(x, t) in damage "
                        "scenes (muParser, with min and max). Its largest "
                        "nodal error is then printed and written to "
                        "statistics.csv.");
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
  Verification<dim>::parse_parameters(ParameterHandler  &prm,
                                      const unsigned int n_components)
  {
    n_fe_components = n_components;
    prm.enter_subsection("Verification");
    exact_damage.reset();
    if (!prm.get("Exact damage").empty())
      {
        VPContactCheckParameter(n_components > dim,
                                "Verification/Exact damage",
                                prm.get("Exact damage"),
                                "this scene has no damage field (Damage/Model "
                                "= none); leave the entry empty.");
        exact_damage = parse_function_entry<dim>(
          prm,
          "Verification",
          "Exact damage",
          1,
          parse_function_constants(prm,
                                   "Verification",
                                   "Function constants",
                                   coordinate_variables(dim)));
      }
    if (!prm.get("Exact displacement").empty())
      {
        const auto constants
          = parse_function_constants(prm,
                                     "Verification",
                                     "Function constants",
                                     coordinate_variables(dim));
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
          = parse_function_constants(prm,
                                     "Verification",
                                     "Function constants",
                                     coordinate_variables(dim));
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
  Verification<dim>::has_exact_damage() const
  {
    return exact_damage != nullptr;
  }



  template <int dim>
  double
  Verification<dim>::damage_error(const DoFHandler<dim> &dof_handler,
                                  const LA::MPI::Vector &solution,
                                  const double           time)
  {
    exact_damage->set_time(time);
    const VectorFunctionFromScalarFunctionObject<dim> exact(
      [&](const Point<dim> &p) { return exact_damage->value(p); },
      dim,
      n_fe_components);
    ComponentMask mask(n_fe_components, false);
    mask.set(dim, true);
    LA::MPI::Vector nodal(dof_handler.locally_owned_dofs(),
                          solution.get_mpi_communicator());
    VectorTools::interpolate(dof_handler, exact, nodal, mask);
    double error = 0;
    for (const auto dof : DoFTools::extract_dofs(dof_handler, mask))
      error = std::max(error, std::abs(nodal(dof) - solution(dof)));
    error = Utilities::MPI::max(error, solution.get_mpi_communicator());
    max_damage_error = std::max(max_damage_error, error);
    return error;
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
  Verification<dim>::compute_errors(const DoFHandler<dim> &dof_handler,
                                    const LA::MPI::Vector &solution,
                                    const double           time,
                                    const double           u_max)
  {
    Assert(is_active(), ExcInternalError());
    exact_displacement->set_time(time);

    Errors          errors;
    LA::MPI::Vector nodal(dof_handler.locally_owned_dofs(),
                          solution.get_mpi_communicator());
    // The exact displacement on all components of the element (the damage
    // component, if any, gets 0 and is left out of the errors).
    const DisplacementFunction<dim>    padded(*exact_displacement,
                                           n_fe_components);
    const ComponentSelectFunction<dim> displacement_only(std::make_pair(0u,
                                                                        dim),
                                                         n_fe_components);
    VectorTools::interpolate(dof_handler, padded, nodal);
    LA::MPI::Vector owned(nodal);
    owned = solution; // imports the locally owned part of the ghosted vector
    nodal -= owned;
    if (n_fe_components > dim) // the damage entries are not displacement
      {
        ComponentMask damage_mask(n_fe_components, false);
        damage_mask.set(dim, true);
        const IndexSet damage
          = DoFTools::extract_dofs(dof_handler, damage_mask);
        for (const auto dof : damage)
          nodal(dof) = 0.;
        nodal.compress(VectorOperation::insert);
      }
    errors.max_nodal = nodal.linfty_norm();

    Vector<float> cellwise(dof_handler.get_triangulation().n_active_cells());
    VectorTools::integrate_difference(
      get_default_linear_mapping(dof_handler.get_triangulation()),
      dof_handler,
      solution,
      padded,
      cellwise,
      dof_handler.get_fe()
        .reference_cell()
        .template get_gauss_type_quadrature<dim>(3),
      VectorTools::L2_norm,
      &displacement_only);
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
    if (has_exact_damage())
      text += line("nodal damage", max_damage_error, 1.);
    return text;
  }



  template <int dim>
  std::map<std::string, double>
  Verification<dim>::running_maxima() const
  {
    return {{"max_nodal_error", max_nodal_error},
            {"max_displacement", max_displacement},
            {"max_damage_error", max_damage_error},
            {"max_stress_error", max_stress_error},
            {"max_stress", max_stress}};
  }



  template <int dim>
  void
  Verification<dim>::restore_running_maxima(
    const std::map<std::string, double> &maxima)
  {
    const auto value = [&](const std::string &name) {
      const auto found = maxima.find(name);
      return found == maxima.end() ? 0. : found->second;
    };
    max_nodal_error  = value("max_nodal_error");
    max_displacement = value("max_displacement");
    max_damage_error = value("max_damage_error");
    max_stress_error = value("max_stress_error");
    max_stress       = value("max_stress");
  }



  template class Verification<2>;
  template class Verification<3>;
} // namespace VPContact
