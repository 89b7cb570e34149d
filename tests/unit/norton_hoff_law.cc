// Unit test: the Norton-Hoff law G = -(1 - zeta) A |dev sigma|^(m-1) dev sigma
// against closed forms. (1) G at a given stress, in 2D and 3D. (2) dG/dsigma
// against central differences of G. (3) The relaxation of a deviatoric
// stress at fixed strain, d sigma/dt = G(sigma): sigma keeps its direction and
// its norm solves |s|' = -(1 - zeta) A |s|^m, so that
//   |s(t)|^(1-m) = |s_0|^(1-m) + (m - 1)(1 - zeta) A t.
// Forward and backward Euler (implicit_stress_update) approach it at first
// order in the time step.
#include <vpcontact/material/norton_hoff_law.h>

#include <cmath>
#include <cstdio>
#include <iostream>

using namespace VPContact;

namespace
{
  template <int dim>
  SymmetricTensor<2, dim>
  sample_stress()
  {
    SymmetricTensor<2, dim> sigma;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = (i == j ? 3. - 2. * i : 1. + 0.5 * i + 0.25 * j);
    return sigma;
  }



  // (1) G against -(1 - zeta) A |s|^(m-1) s written out component by
  // component, with s = sigma - tr(sigma)/dim I.
  template <int dim>
  void
  check_rate(const double A, const double m, const double zeta)
  {
    const NortonHoffLaw<dim>      law(A, m);
    const SymmetricTensor<2, dim> sigma = sample_stress<dim>();
    double                        tr    = 0;
    for (unsigned int i = 0; i < dim; ++i)
      tr += sigma[i][i];
    SymmetricTensor<2, dim> s = sigma;
    for (unsigned int i = 0; i < dim; ++i)
      s[i][i] -= tr / dim;
    double norm2 = 0;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        norm2 += s[i][j] * s[i][j];
    const SymmetricTensor<2, dim> expected
      = -(1 - zeta) * A * std::pow(norm2, (m - 1) / 2) * s;
    const SymmetricTensor<2, dim> G = law.rate(sigma, sigma, zeta);
    std::printf("%dD A = %g m = %g zeta = %g: |G| = %.10e, |G - closed "
                "form| / |G| < 1e-14: %s, trace G = 0: %s\n",
                dim,
                A,
                m,
                zeta,
                G.norm(),
                (G - expected).norm() < 1e-14 * G.norm() ? "yes" : "no",
                std::abs(trace(G)) < 1e-13 * G.norm() ? "yes" : "no");
  }



  // (2) dG/dsigma against central differences, entry by entry.
  template <int dim>
  void
  check_derivative(const double A, const double m)
  {
    const NortonHoffLaw<dim>      law(A, m);
    const SymmetricTensor<2, dim> sigma = sample_stress<dim>();
    const SymmetricTensor<4, dim> D = law.rate_derivative(sigma, sigma, 0.3);
    double                        largest_difference = 0;
    const double                  h                  = 1e-6;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = k; l < dim; ++l)
        {
          SymmetricTensor<2, dim> plus = sigma, minus = sigma;
          plus[k][l] += h;
          minus[k][l] -= h;
          const SymmetricTensor<2, dim> difference
            = (law.rate(plus, sigma, 0.3) - law.rate(minus, sigma, 0.3))
              / (2 * h);
          // A change of the entry (k, l) of a symmetric tensor changes both
          // (k, l) and (l, k): the directional derivative is D : E_kl.
          SymmetricTensor<2, dim> direction;
          direction[k][l] = 1.;
          largest_difference
            = std::max(largest_difference,
                       (difference - D * direction).norm() / D.norm());
        }
    std::printf("%dD m = %g: dG/dsigma against central differences: %s\n",
                dim,
                m,
                largest_difference < 1e-7 ? "agree to 1e-7" : "DIFFER");
  }



  // (3) Relaxation from a deviatoric stress to t = T with steps k, forward
  // and backward Euler; returns the relative errors of |s(T)|.
  std::pair<double, double>
  relaxation_errors(const double       A,
                    const double       m,
                    const double       zeta,
                    const unsigned int n_steps)
  {
    const NortonHoffLaw<2> law(A, m);
    SymmetricTensor<2, 2>  s0;
    s0[0][0]       = 1.;
    s0[1][1]       = -1.;
    s0[0][1]       = 0.5;
    const double T = 1.;
    const double k = T / n_steps;
    const double exact_norm
      = std::pow(std::pow(s0.norm(), 1 - m) + (m - 1) * (1 - zeta) * A * T,
                 1 / (1 - m));
    SymmetricTensor<2, 2> forward = s0, backward = s0;
    for (unsigned int n = 0; n < n_steps; ++n)
      {
        forward += k * law.rate(forward, s0, zeta);
        backward = implicit_stress_update<2>(law,
                                             backward,
                                             s0,
                                             zeta,
                                             k,
                                             identity_tensor<2>())
                     .stress;
      }
    return {std::abs(forward.norm() - exact_norm) / exact_norm,
            std::abs(backward.norm() - exact_norm) / exact_norm};
  }
} // namespace



int
main()
{
  check_rate<2>(2., 3., 0.);
  check_rate<2>(2., 1., 0.25);
  check_rate<3>(0.5, 2.5, 0.);
  check_derivative<2>(2., 3.);
  check_derivative<3>(0.5, 2.5);
  check_derivative<2>(2., 1.);

  std::printf("zero stress: |G| = %g\n",
              NortonHoffLaw<2>(2., 3.)
                .rate(SymmetricTensor<2, 2>(), SymmetricTensor<2, 2>(), 0.)
                .norm());
  std::printf("explicit step limit: m = 1, A = 4: %g (expected 0.5); "
              "m = 3: %g (expected inf)\n",
              NortonHoffLaw<2>(4., 1.).explicit_step_limit(),
              NortonHoffLaw<2>(4., 3.).explicit_step_limit());

  std::printf("relaxation to T = 1, A = 2, m = 3, zeta = 0.25:\n");
  std::printf("  steps  forward Euler error  order  backward Euler error  "
              "order\n");
  std::pair<double, double> previous{0, 0};
  for (const unsigned int n_steps : {20u, 40u, 80u, 160u})
    {
      const auto errors = relaxation_errors(2., 3., 0.25, n_steps);
      if (previous.first > 0)
        std::printf("  %5u  %19.2e  %5.2f  %20.2e  %5.2f\n",
                    n_steps,
                    errors.first,
                    std::log2(previous.first / errors.first),
                    errors.second,
                    std::log2(previous.second / errors.second));
      else
        std::printf("  %5u  %19.2e  %5s  %20.2e  %5s\n",
                    n_steps,
                    errors.first,
                    "-",
                    errors.second,
                    "-");
      previous = errors;
    }
}
