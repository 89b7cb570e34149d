// The viscoplastic function G(sigma, eps(u), zeta) of the constitutive law
// (1): a small class per law, chosen by name in the section "Viscoplasticity".
#ifndef vpcontact_viscoplastic_law_h
#define vpcontact_viscoplastic_law_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * The truncation Phi_L of the paper's (19): every component of @p tau
   * clipped to [-L, L].
   */
  template <int dim>
  SymmetricTensor<2, dim>
  truncate(const SymmetricTensor<2, dim> &tau, const double L);

  /**
   * A viscoplastic law: the rate G(sigma, eps, zeta) that the forward Euler
   * step adds to the stress, sigma_n = sigma_{n-1} + k E eps(w) + k G_{n-1}.
   * No finite element types here: a law is a function of tensors.
   */
  template <int dim>
  class ViscoplasticLaw
  {
  public:
    virtual ~ViscoplasticLaw() = default;

    /// G(sigma, eps, zeta) [Pa/s].
    virtual SymmetricTensor<2, dim>
    rate(const SymmetricTensor<2, dim> &stress,
         const SymmetricTensor<2, dim> &strain,
         const double                   damage) const = 0;

    /**
     * dG/dsigma at (sigma, eps, zeta), for the implicit (backward Euler)
     * step: the Jacobian of its local Newton solve and its tangent.
     */
    virtual SymmetricTensor<4, dim>
    rate_derivative(const SymmetricTensor<2, dim> &stress,
                    const SymmetricTensor<2, dim> &strain,
                    const double                   damage) const = 0;

    /**
     * The largest time step for which the explicit step is stable, where
     * the law knows it (for G = -sigma/eta the amplification factor of one
     * step is 1 - k/eta, so k <= 2 eta); infinity where no limit is known.
     */
    virtual double
    explicit_step_limit() const;

    /// Whether G is identically zero (then no viscoplastic work is done).
    virtual bool
    is_zero() const;

    /// A description for the screen, e.g. "Maxwell -sigma/eta, eta = 0.1".
    virtual std::string
    description() const = 0;
  };



  /// G = 0: linear elasticity.
  template <int dim>
  class NoViscoplasticity : public ViscoplasticLaw<dim>
  {
  public:
    SymmetricTensor<2, dim>
    rate(const SymmetricTensor<2, dim> &stress,
         const SymmetricTensor<2, dim> &strain,
         const double                   damage) const override;

    SymmetricTensor<4, dim>
    rate_derivative(const SymmetricTensor<2, dim> &stress,
                    const SymmetricTensor<2, dim> &strain,
                    const double                   damage) const override;

    bool
    is_zero() const override;

    std::string
    description() const override;
  };



  /**
   * The paper's law (18): G = -(1 - zeta) Phi_L(sigma). It relaxes the
   * stress only where the material is damaged (zeta < 1); its Lipschitz
   * constant in sigma is (1 - zeta) <= 1, so k <= 2 [s] is stable.
   */
  template <int dim>
  class DamageTruncatedLaw : public ViscoplasticLaw<dim>
  {
  public:
    explicit DamageTruncatedLaw(const double truncation);

    SymmetricTensor<2, dim>
    rate(const SymmetricTensor<2, dim> &stress,
         const SymmetricTensor<2, dim> &strain,
         const double                   damage) const override;

    SymmetricTensor<4, dim>
    rate_derivative(const SymmetricTensor<2, dim> &stress,
                    const SymmetricTensor<2, dim> &strain,
                    const double                   damage) const override;

    double
    explicit_step_limit() const override;

    std::string
    description() const override;

  private:
    const double L;
  };



  /**
   * Linear Maxwell relaxation G = -sigma/eta, or, with a truncation L, the
   * Lipschitz-bounded -Phi_L(sigma)/eta. Lipschitz constant 1/eta.
   */
  template <int dim>
  class MaxwellLaw : public ViscoplasticLaw<dim>
  {
  public:
    /// @p truncation = infinity: no truncation.
    MaxwellLaw(const double relaxation_time, const double truncation);

    SymmetricTensor<2, dim>
    rate(const SymmetricTensor<2, dim> &stress,
         const SymmetricTensor<2, dim> &strain,
         const double                   damage) const override;

    SymmetricTensor<4, dim>
    rate_derivative(const SymmetricTensor<2, dim> &stress,
                    const SymmetricTensor<2, dim> &strain,
                    const double                   damage) const override;

    double
    explicit_step_limit() const override;

    std::string
    description() const override;

  private:
    const double eta;
    const double L;
  };



  /// The result of the implicit stress update at one quadrature point.
  template <int dim>
  struct ImplicitStress
  {
    SymmetricTensor<2, dim> stress;
    /// d sigma_n / d eps(du) = (I - k dG/dsigma)^{-1} E.
    SymmetricTensor<4, dim> tangent;
    unsigned int            iterations = 0;
  };

  /**
   * The backward Euler step of sigma_dot = E eps(u_dot) + G: solve
   *   sigma - k G(sigma, eps, zeta) = trial,  trial = sigma_{n-1} + E eps(du),
   * by Newton's method at one quadrature point, starting from the trial
   * stress. Throws if it does not converge in 50 iterations (to 1e-12 of
   * the trial stress).
   */
  template <int dim>
  ImplicitStress<dim>
  implicit_stress_update(const ViscoplasticLaw<dim>    &law,
                         const SymmetricTensor<2, dim> &trial,
                         const SymmetricTensor<2, dim> &strain,
                         const double                   damage,
                         const double                   time_step,
                         const SymmetricTensor<4, dim> &stiffness);

  /**
   * The laws a scene can name in Viscoplasticity/Law, in the manner of
   * ASPECT's plugins: a law registers itself, for 2D and 3D, with its name,
   * a sentence for the parameter documentation, a function that declares its
   * own parameters (called inside the section "Viscoplasticity") and one that
   * creates the law from them. VPCONTACT_REGISTER_VISCOPLASTIC_LAW does this
   * from the law's own source file, so that adding a law touches no other
   * file (doc/design.md walks through an example).
   */
  template <int dim>
  class ViscoplasticLawRegistry
  {
  public:
    using Declare = std::function<void(ParameterHandler &)>;
    using Create  = std::function<std::unique_ptr<ViscoplasticLaw<dim>>(
      ParameterHandler &)>;

    /// Register a law; returns true (for the static initialisers).
    static bool
    add(const std::string &name,
        const std::string &documentation,
        const Declare     &declare,
        const Create      &create);

    /// The names, alphabetically, as a Patterns::Selection ("a|b|c").
    static std::string
    names();

    /// "'name': documentation" of every law, alphabetically.
    static std::string
    documentation();

    /// Declare the parameters of every law (inside "Viscoplasticity").
    static void
    declare_parameters(ParameterHandler &prm);

    /// Create the law @p name from its parameters (inside
    /// "Viscoplasticity").
    static std::unique_ptr<ViscoplasticLaw<dim>>
    create(const std::string &name, ParameterHandler &prm);

  private:
    struct Entry
    {
      std::string documentation;
      Declare     declare;
      Create      create;
    };

    static std::map<std::string, Entry> &
    entries();
  };



/**
 * Register the law template @p classname (with a static
 * declare_parameters(ParameterHandler &) and a constructor from the
 * ParameterHandler, both inside the section "Viscoplasticity") under @p name,
 * for 2D and 3D. One line in the law's source file, at namespace scope in
 * namespace VPContact.
 */
#define VPCONTACT_REGISTER_VISCOPLASTIC_LAW(classname, name, documentation) \
  template class classname<2>;                                              \
  template class classname<3>;                                              \
  namespace                                                                 \
  {                                                                         \
    [[maybe_unused]] const bool classname##_registered                      \
      = ViscoplasticLawRegistry<2>::add(                                    \
          name,                                                             \
          documentation,                                                    \
          &classname<2>::declare_parameters,                                \
          [](ParameterHandler &prm) {                                       \
            return std::make_unique<classname<2>>(prm);                     \
          })                                                                \
        && ViscoplasticLawRegistry<3>::add(                                 \
          name,                                                             \
          documentation,                                                    \
          &classname<3>::declare_parameters,                                \
          [](ParameterHandler &prm) {                                       \
            return std::make_unique<classname<3>>(prm);                     \
          });                                                               \
  }



  /**
   * Section "Viscoplasticity": which law, the entries common to all laws
   * (time integration, divergence safeguard, the truncation L), and the
   * registered laws' own entries.
   */
  template <int dim>
  class ViscoplasticityParameters
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /// The law named in the section, created from its parameters.
    std::unique_ptr<ViscoplasticLaw<dim>>
    create_law(ParameterHandler &prm) const;

    /**
     * A run stops when some stress component exceeds this multiple of
     * Young's modulus: a strain of that size means the explicit step has
     * blown up, not that the body deforms.
     */
    double
    divergence_limit() const;

    /// Whether G is treated by backward Euler (else forward Euler).
    bool
    implicit() const;

  private:
    bool        implicit_step     = false;
    double      divergence_factor = 1e6;
    std::string law_name          = "none";
  };
} // namespace VPContact

#endif
