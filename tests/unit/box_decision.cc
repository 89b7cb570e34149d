// Unit test: the primal-dual active set decision for the damage bounds
// [0, 1] (lambda = residual, c > 0): upper where lambda + c (zeta - 1) > 0,
// lower where lambda + c zeta < 0, free otherwise.
#include <vpcontact/damage/damage_bounds.h>

#include <iostream>

using namespace VPContact;

void
show(const double lambda, const double zeta, const double c)
{
  const auto s = box_decision(lambda, zeta, c);
  std::cout << "lambda = " << lambda << ", zeta = " << zeta << ", c = " << c
            << ": "
            << (s == BoundStatus::upper ? "upper (zeta = 1)" :
                s == BoundStatus::lower ? "lower (zeta = 0)" :
                                          "free")
            << std::endl;
}

int
main()
{
  show(0, 0.5, 1);    // interior, balanced: free
  show(0, 1.2, 1);    // above 1: upper
  show(0, -0.1, 1);   // below 0: lower
  show(2, 1, 1);      // at 1 and pushed up: upper
  show(-0.5, 1, 1);   // at 1, pulled down less than c: free (leaves 1)
  show(-2, 1, 1);     // at 1, pulled down more than c zeta: lower (Newton
                      // step across the box)
  show(-2, 0, 1);     // at 0 and pulled down: lower
  show(0.5, 0, 1);    // at 0, pushed up less than c: free (leaves 0)
  show(2, 0, 1);      // at 0, pushed up more than c (1 - zeta): upper
  show(0.5, 0.9, 10); // 0.5 + 10 (-0.1) < 0: free
  show(1.5, 0.9, 10); // 1.5 - 1 > 0: upper
}
