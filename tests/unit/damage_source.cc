// Unit test: the damage source phi as an expression of the local state. The
// default phi = lambda_w - lambda_E eps:eps / 2 at eps = (0.1, -0.03, 0.02)
// is 0.5 - 50 (0.01 + 0.0009 + 2 * 0.0004) = -0.085; the other variables
// (zeta, stress components, energy = sigma:eps/2, von_mises, x, y, t) are
// checked one by one, and an unknown name is refused with a message.
#include <vpcontact/damage/damage_source.h>

#include <deal.II/base/exceptions.h>

#include <iostream>

using namespace VPContact;

int
main()
{
  deal_II_exceptions::disable_abort_on_exception();
  SymmetricTensor<2, 2> eps, sigma;
  eps[0][0]   = 0.1;
  eps[1][1]   = -0.03;
  eps[0][1]   = 0.02;
  sigma[0][0] = 7;
  sigma[1][1] = 0;
  sigma[0][1] = 0;
  const Point<2> x(0.25, 0.75);

  const std::map<std::string, double> constants
    = {{"lambda_w", 0.5}, {"lambda_E", 100}};
  for (const std::string expression : {"lambda_w - 0.5*lambda_E*eps_eps",
                                       "zeta",
                                       "eps_xx + 10*eps_yy + 100*eps_xy",
                                       "sigma_xx",
                                       "energy",
                                       "von_mises",
                                       "x + 10*y + 100*t"})
    {
      const DamageSource<2> phi(expression, constants, "Damage/Source");
      std::cout << expression << " = " << phi.value(eps, sigma, 0.4, x, 2.)
                << std::endl;
    }
  std::cout << "expected: -0.085, 0.4, 1.8, 7, 0.35, 7, 207.75" << std::endl;

  try
    {
      const DamageSource<2> phi("lambda_w - strain",
                                constants,
                                "Damage/Source");
    }
  catch (const ExceptionBase &e)
    {
      std::cout << "refused: ";
      e.print_info(std::cout);
    }
}
