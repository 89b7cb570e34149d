// The viscoplastic laws G = 0, the paper's and Maxwell's, the registry of
// laws, and the section "Viscoplasticity".
#include <vpcontact/input/input_error.h>
#include <vpcontact/material/viscoplastic_law.h>

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
  bool
  ViscoplasticLawRegistry<dim>::add(const std::string &name,
                                    const std::string &documentation,
                                    const Declare     &declare,
                                    const Create      &create)
  {
    const bool inserted
      = entries().emplace(name, Entry{documentation, declare, create}).second;
    Assert(inserted, ExcMessage("Two viscoplastic laws named " + name));
    (void)inserted;
    return true;
  }



  template <int dim>
  std::string
  ViscoplasticLawRegistry<dim>::names()
  {
    std::string result;
    for (const auto &[name, entry] : entries())
      result += (result.empty() ? "" : "|") + name;
    return result;
  }



  template <int dim>
  std::string
  ViscoplasticLawRegistry<dim>::documentation()
  {
    std::string result;
    for (const auto &[name, entry] : entries())
      result
        += (result.empty() ? "'" : " '") + name + "': " + entry.documentation;
    return result;
  }



  template <int dim>
  void
  ViscoplasticLawRegistry<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (const auto &[name, entry] : entries())
      if (entry.declare)
        entry.declare(prm);
  }



  template <int dim>
  std::unique_ptr<ViscoplasticLaw<dim>>
  ViscoplasticLawRegistry<dim>::create(const std::string &name,
                                       ParameterHandler  &prm)
  {
    const auto entry = entries().find(name);
    AssertThrow(entry != entries().end(),
                ExcMessage("Viscoplasticity/Law = " + name
                           + ": unknown law (one of " + names() + ")."));
    return entry->second.create(prm);
  }



  template <int dim>
  std::map<std::string, typename ViscoplasticLawRegistry<dim>::Entry> &
  ViscoplasticLawRegistry<dim>::entries()
  {
    // Constructed on first use, so that laws registered from the static
    // initialisers of other files find it whatever the order of those.
    static std::map<std::string, Entry> registered_laws;
    return registered_laws;
  }



  namespace
  {
    // The laws of this file: G = 0, the paper's law and Maxwell's. Their
    // entries sit directly in "Viscoplasticity" (scenes written for the
    // first release name them there).
    template <int dim>
    void
    declare_maxwell_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Relaxation time",
                        "1",
                        Patterns::Double(0),
                        "eta of the Maxwell law [s]. Must be positive. The "
                        "explicit step is stable only for Time step <= 2 eta.");
      prm.declare_entry("Truncate Maxwell",
                        "false",
                        Patterns::Bool(),
                        "Maxwell law only: relax Phi_L(sigma) instead of "
                        "sigma, which bounds the rate by L/eta.");
    }



    // The entry "Truncation L", which the laws that truncate read (and
    // only they: it means nothing to the others).
    double
    truncation_entry(ParameterHandler &prm)
    {
      const double truncation = prm.get_double("Truncation L");
      VPContactCheckParameter(truncation > 0,
                              "Viscoplasticity/Truncation L",
                              truncation,
                              "must be positive [Pa].");
      return truncation;
    }



    template <int dim>
    bool
    register_builtin_laws()
    {
      using Registry = ViscoplasticLawRegistry<dim>;
      Registry::add("none",
                    "G = 0 (linear elasticity).",
                    nullptr,
                    [](ParameterHandler &) {
                      return std::make_unique<NoViscoplasticity<dim>>();
                    });
      Registry::add("paper",
                    "G = -(1 - zeta) Phi_L(sigma), the paper's (18)-(19), "
                    "with Phi_L the component-wise truncation at +-L.",
                    nullptr,
                    [](ParameterHandler &prm) {
                      return std::make_unique<DamageTruncatedLaw<dim>>(
                        truncation_entry(prm));
                    });
      Registry::add(
        "maxwell",
        "G = -sigma/eta (or -Phi_L(sigma)/eta with 'Truncate Maxwell').",
        &declare_maxwell_parameters<dim>,
        [](ParameterHandler &prm) {
          const double eta = prm.get_double("Relaxation time");
          VPContactCheckParameter(eta > 0,
                                  "Viscoplasticity/Relaxation time",
                                  eta,
                                  "must be positive [s].");
          return std::make_unique<MaxwellLaw<dim>>(
            eta,
            prm.get_bool("Truncate Maxwell") ?
              truncation_entry(prm) :
              std::numeric_limits<double>::infinity());
        });
      return true;
    }

    [[maybe_unused]] const bool builtin_laws_registered
      = register_builtin_laws<2>() && register_builtin_laws<3>();
  } // namespace



  template <int dim>
  void
  ViscoplasticityParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Viscoplasticity");
    {
      prm.declare_entry("Law",
                        "none",
                        Patterns::Selection(
                          ViscoplasticLawRegistry<dim>::names()),
                        "The viscoplastic function G of the law "
                        "sigma_dot = E eps(u_dot) + G. "
                          + ViscoplasticLawRegistry<dim>::documentation());
      prm.declare_entry("Truncation L",
                        "1000",
                        Patterns::Double(0),
                        "L of the truncation Phi_L [Pa], for 'paper' and the "
                        "truncated Maxwell law. Must be positive.");
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
      ViscoplasticLawRegistry<dim>::declare_parameters(prm);
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  ViscoplasticityParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Viscoplasticity");
    law_name          = prm.get("Law");
    divergence_factor = prm.get_double("Divergence limit");
    implicit_step     = (prm.get("Time integration") == "implicit");
    prm.leave_subsection();
    VPContactCheckParameter(divergence_factor > 0,
                            "Viscoplasticity/Divergence limit",
                            divergence_factor,
                            "must be positive, e.g. 1e6.");
  }



  template <int dim>
  std::unique_ptr<ViscoplasticLaw<dim>>
  ViscoplasticityParameters<dim>::create_law(ParameterHandler &prm) const
  {
    prm.enter_subsection("Viscoplasticity");
    auto law = ViscoplasticLawRegistry<dim>::create(law_name, prm);
    prm.leave_subsection();
    return law;
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
  template class ViscoplasticLawRegistry<2>;
  template class ViscoplasticLawRegistry<3>;
  template class ViscoplasticityParameters<2>;
  template class ViscoplasticityParameters<3>;
} // namespace VPContact
