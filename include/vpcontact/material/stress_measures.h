// Scalar measures of a stress tensor that users plot: the von Mises norm.
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
    SymmetricTensor<2, 3> s3;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        s3[i][j] = s[i][j];
    const SymmetricTensor<2, 3> dev = deviator(s3);
    return std::sqrt(1.5 * scalar_product(dev, dev));
  }
} // namespace VPContact

#endif
