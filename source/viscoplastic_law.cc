// The viscoplastic laws and the section "Viscoplasticity".
#include <vpcontact/input_error.h>
#include <vpcontact/viscoplastic_law.h>

#include <algorithm>

namespace VPContact
{
  template <int dim>
  SymmetricTensor<2, dim>
  truncate(const SymmetricTensor<2, dim> &tau, const double L)
  {
    SymmetricTensor<2, dim> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        result[i][j] = std::clamp(tau[i][j], -L, L);
    return result;
  }



  namespace
  {
    // d Phi_L / d sigma: the identity on the components inside [-L, L],
    // zero on the clipped ones.
    template <int dim>
    SymmetricTensor<4, dim>
    truncation_derivative(const SymmetricTensor<2, dim> &tau, const double L)
    {
      SymmetricTensor<4, dim> D = identity_tensor<dim>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          if (std::abs(tau[i][j]) > L)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = k; l < dim; ++l)
                D[i][j][k][l] = 0.;
      return D;
    }
  } // namespace



  template <int dim>
  ImplicitStress<dim>
  implicit_stress_update(const ViscoplasticLaw<dim>    &law,
                         const SymmetricTensor<2, dim> &trial,
                         const SymmetricTensor<2, dim> &strain,
                         const double                   damage,
                         const double                   k,
                         const SymmetricTensor<4, dim> &stiffness)
  {
    // Newton for R(sigma) = sigma - k G(sigma) - trial = 0 with the
    // Jacobian J = I - k dG/dsigma; for the laws here G is piecewise linear
    // in sigma and Newton ends in one or two steps.
    constexpr unsigned int max_iterations = 50;
    const double           tolerance      = 1e-12 * (trial.norm() + 1e-300);
    ImplicitStress<dim>    result;
    result.stress = trial;
    for (; result.iterations < max_iterations; ++result.iterations)
      {
        const SymmetricTensor<2, dim> residual
          = result.stress - k * law.rate(result.stress, strain, damage) - trial;
        if (residual.norm() <= tolerance)
          break;
        const SymmetricTensor<4, dim> jacobian
          = identity_tensor<dim>()
            - k * law.rate_derivative(result.stress, strain, damage);
        result.stress -= invert(jacobian) * residual;
      }
    AssertThrow(result.iterations < max_iterations,
                ExcMessage("The implicit viscoplastic stress update (local "
                           "Newton at a quadrature point, law: "
                           + law.description()
                           + ") did not converge in 50 iterations. Reduce "
                             "Time/Time step or use the explicit step."));
    result.tangent
      = invert(identity_tensor<dim>()
               - k * law.rate_derivative(result.stress, strain, damage))
        * stiffness;
    return result;
  }



  template <int dim>
  double
  ViscoplasticLaw<dim>::explicit_step_limit() const
  {
    return std::numeric_limits<double>::infinity();
  }



  template <int dim>
  bool
  ViscoplasticLaw<dim>::is_zero() const
  {
    return false;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  NoViscoplasticity<dim>::rate(const SymmetricTensor<2, dim> &,
                               const SymmetricTensor<2, dim> &,
                               const double) const
  {
    return SymmetricTensor<2, dim>();
  }



  template <int dim>
  SymmetricTensor<4, dim>
  NoViscoplasticity<dim>::rate_derivative(const SymmetricTensor<2, dim> &,
                                          const SymmetricTensor<2, dim> &,
                                          const double) const
  {
    return SymmetricTensor<4, dim>();
  }



  template <int dim>
  bool
  NoViscoplasticity<dim>::is_zero() const
  {
    return true;
  }



  template <int dim>
  std::string
  NoViscoplasticity<dim>::description() const
  {
    return "none (G = 0, linear elasticity)";
  }



  template <int dim>
  DamageTruncatedLaw<dim>::DamageTruncatedLaw(const double truncation)
    : L(truncation)
  {}



  template <int dim>
  SymmetricTensor<2, dim>
  DamageTruncatedLaw<dim>::rate(const SymmetricTensor<2, dim> &stress,
                                const SymmetricTensor<2, dim> &,
                                const double damage) const
  {
    return -(1. - damage) * truncate(stress, L);
  }



  template <int dim>
  SymmetricTensor<4, dim>
  DamageTruncatedLaw<dim>::rate_derivative(
    const SymmetricTensor<2, dim> &stress,
    const SymmetricTensor<2, dim> &,
    const double damage) const
  {
    return -(1. - damage) * truncation_derivative(stress, L);
  }



  template <int dim>
  double
  DamageTruncatedLaw<dim>::explicit_step_limit() const
  {
    // Lipschitz constant (1 - zeta) <= 1 [1/s].
    return 2.;
  }



  template <int dim>
  std::string
  DamageTruncatedLaw<dim>::description() const
  {
    return "paper, G = -(1 - zeta) Phi_L(sigma), L = " + to_text(L);
  }



  template <int dim>
  MaxwellLaw<dim>::MaxwellLaw(const double relaxation_time,
                              const double truncation)
    : eta(relaxation_time)
    , L(truncation)
  {}



  template <int dim>
  SymmetricTensor<2, dim>
  MaxwellLaw<dim>::rate(const SymmetricTensor<2, dim> &stress,
                        const SymmetricTensor<2, dim> &,
                        const double) const
  {
    if (L == std::numeric_limits<double>::infinity())
      return -stress / eta;
    return -truncate(stress, L) / eta;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  MaxwellLaw<dim>::rate_derivative(const SymmetricTensor<2, dim> &stress,
                                   const SymmetricTensor<2, dim> &,
                                   const double) const
  {
    if (L == std::numeric_limits<double>::infinity())
      return -identity_tensor<dim>() / eta;
    return -truncation_derivative(stress, L) / eta;
  }



  template <int dim>
  double
  MaxwellLaw<dim>::explicit_step_limit() const
  {
    return 2. * eta;
  }



  template <int dim>
  std::string
  MaxwellLaw<dim>::description() const
  {
    if (L == std::numeric_limits<double>::infinity())
      return "Maxwell, G = -sigma/eta, eta = " + to_text(eta);
    return "Maxwell truncated, G = -Phi_L(sigma)/eta, eta = " + to_text(eta)
           + ", L = " + to_text(L);
  }



  template <int dim>
  void
  ViscoplasticityParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Viscoplasticity");
    {
      prm.declare_entry("Law",
                        "none",
                        Patterns::Selection("none|paper|maxwell"),
                        "The viscoplastic function G of the law "
                        "sigma_dot = E eps(u_dot) + G. 'none': G = 0 (linear "
                        "elasticity). 'paper': G = -(1 - zeta) Phi_L(sigma), "
                        "the paper's (18)-(19), with Phi_L the component-wise "
                        "truncation at +-L. 'maxwell': G = -sigma/eta (or "
                        "-Phi_L(sigma)/eta with 'Truncate Maxwell').");
      prm.declare_entry("Truncation L",
                        "1000",
                        Patterns::Double(0),
                        "L of the truncation Phi_L [Pa], for 'paper' and the "
                        "truncated Maxwell law. Must be positive.");
      prm.declare_entry("Relaxation time",
                        "1",
                        Patterns::Double(0),
                        "eta of the Maxwell law [s]. Must be positive. The "
                        "explicit step is stable only for Time step <= 2 eta.");
      prm.declare_entry(
        "Time integration",
        "explicit",
        Patterns::Selection("explicit|implicit"),
        "'explicit': forward Euler in G, the paper's scheme (14); stable only "
        "for Time step <= 2 / Lipschitz constant of G (Maxwell: 2 eta), and "
        "refused beyond. 'implicit': backward Euler in G with a local Newton "
        "solve at each quadrature point and a global Newton iteration; "
        "stable for any step (first order), for fast relaxation (small eta). "
        "Not combined with Tresca friction in this release.");
      prm.declare_entry("Divergence limit",
                        "1e6",
                        Patterns::Double(0),
                        "Safeguard: the run stops with a message when a "
                        "stress exceeds this multiple of Young's modulus (a "
                        "strain far beyond the small-strain theory, i.e. an "
                        "unstable explicit step) or is not finite.");
      prm.declare_entry("Truncate Maxwell",
                        "false",
                        Patterns::Bool(),
                        "Maxwell law only: relax Phi_L(sigma) instead of "
                        "sigma, which bounds the rate by L/eta.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  ViscoplasticityParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Viscoplasticity");
    law_name          = prm.get("Law");
    truncation        = prm.get_double("Truncation L");
    relaxation_time   = prm.get_double("Relaxation time");
    truncate_maxwell  = prm.get_bool("Truncate Maxwell");
    divergence_factor = prm.get_double("Divergence limit");
    implicit_step     = (prm.get("Time integration") == "implicit");
    prm.leave_subsection();
    VPContactCheckParameter(divergence_factor > 0,
                            "Viscoplasticity/Divergence limit",
                            divergence_factor,
                            "must be positive, e.g. 1e6.");
    VPContactCheckParameter(truncation > 0,
                            "Viscoplasticity/Truncation L",
                            truncation,
                            "must be positive [Pa].");
    VPContactCheckParameter(relaxation_time > 0,
                            "Viscoplasticity/Relaxation time",
                            relaxation_time,
                            "must be positive [s].");
  }



  template <int dim>
  std::unique_ptr<ViscoplasticLaw<dim>>
  ViscoplasticityParameters<dim>::create_law() const
  {
    if (law_name == "none")
      return std::make_unique<NoViscoplasticity<dim>>();
    if (law_name == "paper")
      return std::make_unique<DamageTruncatedLaw<dim>>(truncation);
    if (law_name == "maxwell")
      return std::make_unique<MaxwellLaw<dim>>(
        relaxation_time,
        truncate_maxwell ? truncation :
                           std::numeric_limits<double>::infinity());
    AssertThrow(false,
                ExcMessage("Viscoplasticity/Law = " + law_name
                           + ": unknown law (none, paper or maxwell)."));
    return nullptr;
  }



  template <int dim>
  double
  ViscoplasticityParameters<dim>::divergence_limit() const
  {
    return divergence_factor;
  }



  template <int dim>
  bool
  ViscoplasticityParameters<dim>::implicit() const
  {
    return implicit_step;
  }



  template ImplicitStress<2>
  implicit_stress_update(const ViscoplasticLaw<2> &,
                         const SymmetricTensor<2, 2> &,
                         const SymmetricTensor<2, 2> &,
                         const double,
                         const double,
                         const SymmetricTensor<4, 2> &);
  template ImplicitStress<3>
  implicit_stress_update(const ViscoplasticLaw<3> &,
                         const SymmetricTensor<2, 3> &,
                         const SymmetricTensor<2, 3> &,
                         const double,
                         const double,
                         const SymmetricTensor<4, 3> &);
  template SymmetricTensor<2, 2>
  truncate(const SymmetricTensor<2, 2> &, const double);
  template SymmetricTensor<2, 3>
  truncate(const SymmetricTensor<2, 3> &, const double);
  template class ViscoplasticLaw<2>;
  template class ViscoplasticLaw<3>;
  template class NoViscoplasticity<2>;
  template class NoViscoplasticity<3>;
  template class DamageTruncatedLaw<2>;
  template class DamageTruncatedLaw<3>;
  template class MaxwellLaw<2>;
  template class MaxwellLaw<3>;
  template class ViscoplasticityParameters<2>;
  template class ViscoplasticityParameters<3>;
} // namespace VPContact
