// Unit test: the elastic tensor against closed forms. Plane stress: a
// uniaxial stress state s e_x has the strain (s/E, -nu s/E) and must be
// mapped back to (s, 0, 0). Plane strain and 3D: a pure shear strain g gives
// the stress 2 mu g, and the uniaxial strain e e_x gives
// sigma_xx = (lambda + 2 mu) e with lambda = E nu / ((1 + nu)(1 - 2 nu)).
#include <vpcontact/material/elastic_material.h>

#include <cstdio>

using namespace VPContact;

template <int dim>
void
check(const typename ElasticMaterial<dim>::PlaneHypothesis hypothesis,
      const char                                          *name)
{
  const double         E = 1000, nu = 0.37, s = 55;
  ElasticMaterial<dim> material;
  material.initialize(E, nu, hypothesis);

  SymmetricTensor<2, dim> eps;
  const bool              plane_stress
    = (dim == 2
       && hypothesis == ElasticMaterial<dim>::PlaneHypothesis::plane_stress);
  if (plane_stress)
    {
      eps[0][0]        = s / E;
      eps[1][1]        = -nu * s / E;
      const auto sigma = material.stress(eps);
      std::printf("%s uniaxial stress: sxx = %.12g (expected %.12g), "
                  "syy = %.3g, sxy = %.3g\n",
                  name,
                  sigma[0][0],
                  s,
                  sigma[1][1],
                  sigma[0][1]);
    }
  else
    {
      eps[0][0]           = 1e-3;
      const auto   sigma  = material.stress(eps);
      const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
      const double mu     = E / (2 * (1 + nu));
      std::printf("%s uniaxial strain: sxx = %.12g (expected %.12g), "
                  "syy = %.12g (expected %.12g)\n",
                  name,
                  sigma[0][0],
                  (lambda + 2 * mu) * 1e-3,
                  sigma[1][1],
                  lambda * 1e-3);
    }
  SymmetricTensor<2, dim> shear;
  shear[0][1]    = 1e-3;
  const auto tau = material.stress(shear);
  std::printf("%s shear: sxy = %.12g (expected 2 mu g = %.12g)\n",
              name,
              tau[0][1],
              2 * material.shear_modulus() * 1e-3);
}

int
main()
{
  check<2>(ElasticMaterial<2>::PlaneHypothesis::plane_stress,
           "2D plane stress");
  check<2>(ElasticMaterial<2>::PlaneHypothesis::plane_strain,
           "2D plane strain");
  check<3>(ElasticMaterial<3>::PlaneHypothesis::plane_strain, "3D");
}
