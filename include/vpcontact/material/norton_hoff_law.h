// The Norton-Hoff power law of viscoplasticity, a registered
// ViscoplasticLaw: Viscoplasticity/Law = norton-hoff.
#ifndef vpcontact_norton_hoff_law_h
#define vpcontact_norton_hoff_law_h

#include <vpcontact/material/viscoplastic_law.h>

namespace VPContact
{
  /**
   * The Norton-Hoff law
   *   G(sigma, eps, zeta) = -(1 - zeta) A |dev sigma|^(m-1) dev sigma,
   * with dev sigma = sigma - (tr sigma / d) I the deviator in d dimensions
   * and |.| the Frobenius norm: a power-law creep of the deviatoric stress
   * that, like the paper's law, acts only where the material is damaged
   * (zeta < 1). m = 1 is a Maxwell law on the deviator with relaxation time
   * 1/A; m > 1 relaxes high stresses faster than low ones.
   *
   * Parameters, in "Viscoplasticity/Norton-Hoff": A [1/(Pa^(m-1) s)] and
   * m >= 1.
   */
  template <int dim>
  class NortonHoffLaw : public ViscoplasticLaw<dim>
  {
  public:
    NortonHoffLaw(const double coefficient, const double exponent);

    /// From "Viscoplasticity/Norton-Hoff" (called inside "Viscoplasticity").
    explicit NortonHoffLaw(ParameterHandler &prm);

    static void
    declare_parameters(ParameterHandler &prm);

    SymmetricTensor<2, dim>
    rate(const SymmetricTensor<2, dim> &stress,
         const SymmetricTensor<2, dim> &strain,
         const double                   damage) const override;

    /**
     * dG/dsigma = -(1 - zeta) A (|s|^(m-1) P + (m-1) |s|^(m-3) s (x) s),
     * s = dev sigma, P the deviatoric projector.
     */
    SymmetricTensor<4, dim>
    rate_derivative(const SymmetricTensor<2, dim> &stress,
                    const SymmetricTensor<2, dim> &strain,
                    const double                   damage) const override;

    /**
     * For m = 1 the Lipschitz constant of G is at most A, so k <= 2/A. For
     * m > 1 it grows with the stress (A m |s|^(m-1)) and no limit is known
     * before the run: the divergence safeguard watches the step instead.
     */
    double
    explicit_step_limit() const override;

    std::string
    description() const override;

  private:
    const double A;
    const double m;
  };
} // namespace VPContact

#endif
