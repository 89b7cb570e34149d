// The isotropic elastic tensor E of the constitutive law (1): Young's modulus,
// Poisson's ratio and, in 2D, the plane stress or plane strain hypothesis.
#ifndef vpcontact_elastic_material_h
#define vpcontact_elastic_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * The elastic tensor of an isotropic, homogeneous material.
   *
   * This class holds no finite element data: it maps a strain to a stress,
   * and nothing else, so that it can be tested against closed forms. In 2D
   * the paper uses the plane stress hypothesis, where the out-of-plane stress
   * vanishes and the effective first Lamé parameter is
   * $\lambda^* = 2\lambda\mu/(\lambda+2\mu) = E\nu/(1-\nu^2)$; plane strain
   * (zero out-of-plane strain) keeps the three-dimensional
   * $\lambda = E\nu/((1+\nu)(1-2\nu))$, as does 3D.
   */
  template <int dim>
  class ElasticMaterial
  {
  public:
    enum class PlaneHypothesis
    {
      plane_stress,
      plane_strain
    };

    /// Declare the entries of the section "Material".
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read and check the entries of the section "Material".
    void
    parse_parameters(ParameterHandler &prm);

    /// Set the data directly (used by unit tests and by parse_parameters).
    void
    initialize(const double          youngs_modulus,
               const double          poisson_ratio,
               const PlaneHypothesis hypothesis);

    /// The fourth-order elastic tensor E.
    const SymmetricTensor<4, dim> &
    stiffness() const;

    /// Its inverse E^{-1}, computed once with it.
    const SymmetricTensor<4, dim> &
    compliance() const;

    /// The stress E eps for a strain eps.
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain) const;

    double
    youngs_modulus() const;

    double
    poisson_ratio() const;

    /// Shear modulus mu = E / (2 (1 + nu)).
    double
    shear_modulus() const;

    /// The (effective, in plane stress) first Lamé parameter.
    double
    first_lame_parameter() const;

    PlaneHypothesis
    plane_hypothesis() const;

  private:
    double                  E          = 1.;
    double                  nu         = 0.;
    PlaneHypothesis         hypothesis = PlaneHypothesis::plane_stress;
    SymmetricTensor<4, dim> elastic_tensor;
    SymmetricTensor<4, dim> compliance_tensor;
  };
} // namespace VPContact

#endif
