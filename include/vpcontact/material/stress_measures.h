// Scalar measures of a stress tensor: the von Mises norm that users plot,
// and the quadratic form of the stored energy.
#ifndef vpcontact_stress_measures_h
#define vpcontact_stress_measures_h

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace VPContact
{
  using namespace dealii;

  /**
   * The von Mises norm sqrt(3/2 dev(s):dev(s)) of a stress tensor. In 2D the
   * tensor is taken as the in-plane part of a three-dimensional stress with
   * s_zz = 0, which is the plane stress state of the paper; for plane strain
   * scenes this is the in-plane von Mises norm (s_zz left out), as the
   * documentation of the output says.
   */
  template <int dim>
  inline double
  von_mises_norm(const SymmetricTensor<2, dim> &s)
  {
    // 3/2 dev(s):dev(s) in closed form: called for every cell in every
    // step, where building the 3D deviator cost more than the rest of the
    // pass.
    static_assert(dim == 2 || dim == 3, "von_mises_norm: 2D or 3D");
    const double s11 = s[0][0], s22 = s[1][1], s12 = s[0][1];
    if constexpr (dim == 2)
      return std::sqrt(s11 * s11 + s22 * s22 - s11 * s22 + 3. * s12 * s12);
    else
      {
        const double s33 = s[2][2];
        return std::sqrt(
          0.5
            * ((s11 - s22) * (s11 - s22) + (s22 - s33) * (s22 - s33)
               + (s33 - s11) * (s33 - s11))
          + 3. * (s12 * s12 + s[0][2] * s[0][2] + s[1][2] * s[1][2]));
      }
  }



  /**
   * The quadratic form sigma : C sigma of a constant symmetric fourth-order
   * tensor C (the compliance, for the energy stored in a stress), as a
   * symmetric matrix on the independent components of sigma: one product
   * per pair of them instead of the contraction with C and then with
   * sigma at every point.
   */
  template <int dim>
  class StressQuadraticForm
  {
  public:
    explicit StressQuadraticForm(const SymmetricTensor<4, dim> &C)
    {
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          matrix[a][b] = unit(a) * C * unit(b);
    }

    double
    operator()(const SymmetricTensor<2, dim> &sigma) const
    {
      double value = 0;
      for (unsigned int a = 0; a < n; ++a)
        {
          double row = 0;
          for (unsigned int b = 0; b < n; ++b)
            row += matrix[a][b] * sigma.access_raw_entry(b);
          value += sigma.access_raw_entry(a) * row;
        }
      return value;
    }

  private:
    static constexpr unsigned int n
      = SymmetricTensor<2, dim>::n_independent_components;
    double matrix[n][n];

    // The symmetric tensor with independent component @p a equal to one
    // (both entries of an off-diagonal one) and the others zero: sigma is
    // the sum of its components times these.
    static SymmetricTensor<2, dim>
    unit(const unsigned int a)
    {
      SymmetricTensor<2, dim> e;
      e.access_raw_entry(a) = 1.;
      return e;
    }
  };
} // namespace VPContact

#endif
