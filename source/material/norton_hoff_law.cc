// The Norton-Hoff power law G = -(1 - zeta) A |dev sigma|^(m-1) dev sigma,
// and its registration as Viscoplasticity/Law = norton-hoff.
#include <vpcontact/input/input_error.h>
#include <vpcontact/material/norton_hoff_law.h>

#include <cmath>

namespace VPContact
{
  namespace
  {
    // An entry of the subsection "Norton-Hoff" of "Viscoplasticity".
    double
    norton_hoff_entry(ParameterHandler &prm, const std::string &name)
    {
      prm.enter_subsection("Norton-Hoff");
      const double value = prm.get_double(name);
      prm.leave_subsection();
      return value;
    }
  } // namespace



  template <int dim>
  NortonHoffLaw<dim>::NortonHoffLaw(const double coefficient,
                                    const double exponent)
    : A(coefficient)
    , m(exponent)
  {
    VPContactCheckParameter(A > 0,
                            "Viscoplasticity/Norton-Hoff/A",
                            A,
                            "must be positive [1/(Pa^(m-1) s)].");
    VPContactCheckParameter(m >= 1,
                            "Viscoplasticity/Norton-Hoff/m",
                            m,
                            "must be at least 1 (m < 1 makes G singular at "
                            "zero stress).");
  }



  template <int dim>
  NortonHoffLaw<dim>::NortonHoffLaw(ParameterHandler &prm)
    : NortonHoffLaw(norton_hoff_entry(prm, "A"), norton_hoff_entry(prm, "m"))
  {}



  template <int dim>
  void
  NortonHoffLaw<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Norton-Hoff");
    {
      prm.declare_entry("A",
                        "1",
                        Patterns::Double(0),
                        "The coefficient A of the Norton-Hoff law "
                        "G = -(1 - zeta) A |dev sigma|^(m-1) dev sigma "
                        "[1/(Pa^(m-1) s)]. Must be positive.");
      prm.declare_entry("m",
                        "1",
                        Patterns::Double(1),
                        "The exponent m >= 1 of the Norton-Hoff law. m = 1: "
                        "linear (Maxwell on the deviator, k <= 2/A); m > 1: "
                        "the explicit step is stable for k A m |dev "
                        "sigma|^(m-1) <= 2, which the run's stress decides.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  SymmetricTensor<2, dim>
  NortonHoffLaw<dim>::rate(const SymmetricTensor<2, dim> &stress,
                           const SymmetricTensor<2, dim> &,
                           const double damage) const
  {
    const SymmetricTensor<2, dim> s    = deviator(stress);
    const double                  norm = s.norm();
    if (norm == 0.)
      return SymmetricTensor<2, dim>();
    return -(1. - damage) * A * std::pow(norm, m - 1.) * s;
  }



  template <int dim>
  SymmetricTensor<4, dim>
  NortonHoffLaw<dim>::rate_derivative(const SymmetricTensor<2, dim> &stress,
                                      const SymmetricTensor<2, dim> &,
                                      const double damage) const
  {
    const SymmetricTensor<2, dim> s    = deviator(stress);
    const double                  norm = s.norm();
    // At zero stress G = O(|s|^m): its derivative there is -(1 - zeta) A P
    // for m = 1 and zero for m > 1.
    if (norm == 0.)
      return (m == 1. ? -(1. - damage) * A * deviator_tensor<dim>() :
                        SymmetricTensor<4, dim>());
    return -(1. - damage) * A
           * (std::pow(norm, m - 1.) * deviator_tensor<dim>()
              + (m - 1.) * std::pow(norm, m - 3.) * outer_product(s, s));
  }



  template <int dim>
  double
  NortonHoffLaw<dim>::explicit_step_limit() const
  {
    if (m == 1.)
      return 2. / A;
    return std::numeric_limits<double>::infinity();
  }



  template <int dim>
  std::string
  NortonHoffLaw<dim>::description() const
  {
    return "Norton-Hoff, G = -(1 - zeta) A |dev sigma|^(m-1) dev sigma, A = "
           + to_text(A) + ", m = " + to_text(m);
  }



  VPCONTACT_REGISTER_VISCOPLASTIC_LAW(
    NortonHoffLaw,
    "norton-hoff",
    "G = -(1 - zeta) A |dev sigma|^(m-1) dev sigma, the Norton-Hoff power "
    "law (parameters in the subsection Norton-Hoff).")
} // namespace VPContact
