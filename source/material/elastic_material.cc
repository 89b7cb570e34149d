// The isotropic elastic tensor and the entries of the section "Material".
#include <vpcontact/input/input_error.h>
#include <vpcontact/material/elastic_material.h>

namespace VPContact
{
  template <int dim>
  void
  ElasticMaterial<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Young's modulus",
                        "1000",
                        Patterns::Double(0),
                        "Young's modulus E of the sound material [Pa = N/m^2]. "
                        "Must be positive.");
      prm.declare_entry("Poisson's ratio",
                        "0.37",
                        Patterns::Double(-1, 0.5),
                        "Poisson's ratio nu [-]. Must lie in (-1, 0.5).");
      prm.declare_entry("Plane hypothesis",
                        "plane stress",
                        Patterns::Selection("plane stress|plane strain"),
                        "2D only: 'plane stress' (sigma_zz = 0, the paper's "
                        "choice) or 'plane strain' (eps_zz = 0). Ignored in "
                        "3D.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  ElasticMaterial<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    const double E_in  = prm.get_double("Young's modulus");
    const double nu_in = prm.get_double("Poisson's ratio");
    // As written: 0.4999999999999 must not read as 0.5 in a message.
    const std::string nu_text = prm.get("Poisson's ratio");
    const auto        hyp     = (prm.get("Plane hypothesis") == "plane stress" ?
                                   PlaneHypothesis::plane_stress :
                                   PlaneHypothesis::plane_strain);
    prm.leave_subsection();

    VPContactCheckParameter(E_in > 0,
                            "Material/Young's modulus",
                            E_in,
                            "the modulus must be positive. Give E > 0 [Pa].");
    // Positive definiteness of the 3D (and plane strain) tensor needs
    // -1 < nu < 1/2; at nu = 1/2 the first Lamé parameter is infinite.
    // Plane stress alone would allow nu < 1, but no isotropic material has
    // nu >= 1/2, so the same range is asked for in all cases.
    VPContactCheckParameter(
      nu_in > -1. && nu_in < 0.5,
      "Material/Poisson's ratio",
      nu_in,
      "outside (-1, 0.5), the elastic tensor is not positive definite (at 0.5 "
      "the material is incompressible). Give -1 < nu < 0.5.");
    // Near nu = 1/2 the bulk modulus outgrows the shear modulus without
    // bound (lambda/mu = 2 nu/(1 - 2 nu)): Q1 elements lock, and the
    // linear solves lose as many digits as lambda/mu has. Plane stress
    // keeps lambda bounded and is not affected.
    constexpr double max_lame_ratio = 1e6;
    VPContactCheckParameter(
      (dim == 2 && hyp == PlaneHypothesis::plane_stress)
        || 2. * nu_in <= max_lame_ratio * (1. - 2. * nu_in),
      "Material/Poisson's ratio",
      nu_text,
      "the material is so nearly incompressible (lambda/mu = "
        + to_text(2. * nu_in / (1. - 2. * nu_in))
        + " > 1e6) that the displacement elements lock and the results "
          "lose their digits. Give nu <= 0.499999 (the near-incompressible "
          "scenes of prm/stiff use 0.4999).");
    initialize(E_in, nu_in, hyp);
  }



  template <int dim>
  void
  ElasticMaterial<dim>::initialize(const double          youngs_modulus,
                                   const double          poisson_ratio,
                                   const PlaneHypothesis hyp)
  {
    E          = youngs_modulus;
    nu         = poisson_ratio;
    hypothesis = hyp;

    // E = lambda I (x) I + 2 mu I_sym, with lambda replaced by its plane
    // stress value in 2D plane stress.
    const double mu     = shear_modulus();
    const double lambda = first_lame_parameter();
    elastic_tensor      = lambda
                       * outer_product(unit_symmetric_tensor<dim>(),
                                       unit_symmetric_tensor<dim>())
                     + 2. * mu * identity_tensor<dim>();
    compliance_tensor = invert(elastic_tensor);
  }



  template <int dim>
  const SymmetricTensor<4, dim> &
  ElasticMaterial<dim>::stiffness() const
  {
    return elastic_tensor;
  }



  template <int dim>
  const SymmetricTensor<4, dim> &
  ElasticMaterial<dim>::compliance() const
  {
    return compliance_tensor;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  ElasticMaterial<dim>::stress(const SymmetricTensor<2, dim> &strain) const
  {
    return elastic_tensor * strain;
  }



  template <int dim>
  double
  ElasticMaterial<dim>::youngs_modulus() const
  {
    return E;
  }



  template <int dim>
  double
  ElasticMaterial<dim>::poisson_ratio() const
  {
    return nu;
  }



  template <int dim>
  double
  ElasticMaterial<dim>::shear_modulus() const
  {
    return E / (2. * (1. + nu));
  }



  template <int dim>
  double
  ElasticMaterial<dim>::first_lame_parameter() const
  {
    if (dim == 2 && hypothesis == PlaneHypothesis::plane_stress)
      return E * nu / (1. - nu * nu);
    return E * nu / ((1. + nu) * (1. - 2. * nu));
  }



  template <int dim>
  typename ElasticMaterial<dim>::PlaneHypothesis
  ElasticMaterial<dim>::plane_hypothesis() const
  {
    return hypothesis;
  }



  template class ElasticMaterial<2>;
  template class ElasticMaterial<3>;
} // namespace VPContact
