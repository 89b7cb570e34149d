// The section "Damage".
#include <vpcontact/damage/damage_model.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parsed_function.h>

#include <cmath>

namespace VPContact
{
  template <int dim>
  void
  DamageModel<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Damage");
    {
      prm.declare_entry("Model",
                        "none",
                        Patterns::Selection("none|gradient"),
                        "'none': no damage field (zeta = 1 in the laws). "
                        "'gradient': the damage zeta in [0, 1] of the "
                        "paper's law (2), a Q1 field solved with its bounds "
                        "by a primal-dual active set method.");
      prm.declare_entry("Diffusion",
                        "0.01",
                        Patterns::Double(0),
                        "Damage diffusion kappa >= 0 [m^2/s].");
      prm.declare_entry("Source",
                        "lambda_w - 0.5*lambda_E*eps_eps",
                        Patterns::Anything(),
                        "The damage source phi [1/s], an expression in zeta, "
                        "the strain (eps_xx, eps_yy, eps_xy, ...), the "
                        "stress (sigma_xx, ...), eps_eps = eps:eps, energy = "
                        "sigma:eps/2, von_mises, x, y (z), t and the "
                        "constants below. Evaluated with the state of the "
                        "previous step.");
      prm.declare_entry("Function constants",
                        "lambda_w:0.5, lambda_E:100",
                        Patterns::Map(Patterns::Anything(), Patterns::Double()),
                        "Named constants for 'Source' and 'Initial damage', "
                        "as name:value pairs.");
      prm.declare_entry("Initial damage",
                        "1",
                        Patterns::Anything(),
                        "zeta_0(x, y (, z)), with values in [0, 1]; 1 is sound "
                        "material.");
      prm.declare_entry("Maximum active set iterations",
                        "50",
                        Patterns::Integer(1, 10000),
                        "The bound iteration of one step stops the run with "
                        "a message if the active sets still change after "
                        "this many iterations.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  DamageModel<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Damage");
    active             = (prm.get("Model") == "gradient");
    kappa              = prm.get_double("Diffusion");
    iteration_cap      = prm.get_integer("Maximum active set iterations");
    source_expression  = prm.get("Source");
    initial_expression = prm.get("Initial damage");
    const auto constants
      = parse_function_constants(prm,
                                 "Damage",
                                 "Function constants",
                                 DamageSource<dim>::variables());
    // Parsed here, so that a wrong expression stops the run at once; the
    // threads' copies are made where they first evaluate it.
    source_constants = constants;
    damage_source.clear();
    damage_source.get() = std::make_shared<DamageSource<dim>>(source_expression,
                                                              constants,
                                                              "Damage/Source");
    initial             = parse_function_entry<dim>(prm,
                                        "Damage",
                                        "Initial damage",
                                        1,
                                        constants);
    initial_constant.reset();
    if (is_constant_expression(initial_expression, coordinate_variables(dim)))
      initial_constant = initial->value(Point<dim>());
    prm.leave_subsection();
  }



  template <int dim>
  bool
  DamageModel<dim>::is_active() const
  {
    return active;
  }



  template <int dim>
  double
  DamageModel<dim>::diffusion() const
  {
    return kappa;
  }



  template <int dim>
  const DamageSource<dim> &
  DamageModel<dim>::source() const
  {
    std::shared_ptr<DamageSource<dim>> &copy = damage_source.get();
    if (!copy)
      copy = std::make_shared<DamageSource<dim>>(source_expression,
                                                 source_constants,
                                                 "Damage/Source");
    return *copy;
  }



  template <int dim>
  const Function<dim> &
  DamageModel<dim>::initial_damage() const
  {
    return *initial;
  }



  template <int dim>
  std::optional<double>
  DamageModel<dim>::constant_initial_damage() const
  {
    return initial_constant;
  }



  template <int dim>
  unsigned int
  DamageModel<dim>::max_iterations() const
  {
    return iteration_cap;
  }



  template <int dim>
  void
  DamageModel<dim>::check_diffusion_length(const double h, const double k) const
  {
    const double length = std::sqrt(kappa * k);
    VPContactCheckParameter(length <= 1e6 * h,
                            "Damage/Diffusion",
                            kappa,
                            "the diffusion length sqrt(kappa k) = "
                              + to_text(length)
                              + " is more than 1e6 times the smallest cell ("
                              + to_text(h)
                              + "): the damage equation is numerically "
                                "singular. Check the units of the geometry, "
                                "Damage/Diffusion and Time/Time step.");
  }



  template <int dim>
  void
  DamageModel<dim>::check_initial_damage_finite(const bool finite) const
  {
    VPContactCheckParameter(finite,
                            "Damage/Initial damage",
                            "'" + initial_expression + "'",
                            "the expression is not finite (NaN or infinity) "
                            "at some node. Check it for divisions by zero, "
                            "roots or logarithms of negative numbers.");
  }



  template <int dim>
  void
  DamageModel<dim>::check_source_finite(const bool         finite,
                                        const unsigned int n,
                                        const double       t) const
  {
    VPContactCheckParameter(finite,
                            "Damage/Source",
                            "'" + source_expression + "'",
                            "at step " + std::to_string(n)
                              + " (t = " + to_text(t)
                              + ") the source is not finite (NaN or infinity) "
                                "at some quadrature point, evaluated in the "
                                "state of the step before. Check it for "
                                "divisions by zero, roots or logarithms of "
                                "negative numbers, and overflow.");
  }



  template <int dim>
  std::string
  DamageModel<dim>::description() const
  {
    if (!active)
      return "none";
    return "gradient, kappa = " + to_text(kappa)
           + ", phi = " + source_expression;
  }



  template class DamageModel<2>;
  template class DamageModel<3>;
} // namespace VPContact
