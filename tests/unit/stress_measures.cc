// Unit test: the von Mises norm. Uniaxial stress s gives |s|; pure shear tau
// gives sqrt(3) |tau|; a hydrostatic 3D state gives 0; in 2D the equibiaxial
// plane stress state (s, s) gives |s| (s_zz = 0 is part of the deviator).
#include <vpcontact/material/stress_measures.h>

#include <cstdio>

using namespace VPContact;

int
main()
{
  SymmetricTensor<2, 2> uniaxial;
  uniaxial[0][0] = -7.;
  SymmetricTensor<2, 2> shear;
  shear[0][1] = 2.;
  SymmetricTensor<2, 2> biaxial;
  biaxial[0][0] = biaxial[1][1]           = 5.;
  const SymmetricTensor<2, 3> hydrostatic = 3. * unit_symmetric_tensor<3>();

  std::printf("uniaxial: %.12g (expected 7)\n", von_mises_norm(uniaxial));
  std::printf("shear: %.12g (expected %.12g)\n",
              von_mises_norm(shear),
              std::sqrt(3.) * 2.);
  std::printf("equibiaxial 2D: %.12g (expected 5)\n", von_mises_norm(biaxial));
  std::printf("hydrostatic 3D: %.3g (expected 0)\n",
              von_mises_norm(hydrostatic));
}
