// Unit test: the viscoplastic laws against closed forms. Phi_L clips each
// component to [-L, L]; the paper's law -(1 - zeta) Phi_L(sigma) vanishes for
// sound material (zeta = 1) and is -Phi_L(sigma) for zeta = 0; Maxwell is
// -sigma/eta, truncated -Phi_L(sigma)/eta; the explicit step limits are
// 2 eta for Maxwell, 2 for the paper's law, none for G = 0.
#include <vpcontact/material/viscoplastic_law.h>

#include <iostream>

using namespace VPContact;

void
print(const std::string &what, const SymmetricTensor<2, 2> &s)
{
  std::cout << what << ": " << s[0][0] << ' ' << s[1][1] << ' ' << s[0][1]
            << std::endl;
}

int
main()
{
  SymmetricTensor<2, 2> sigma;
  sigma[0][0] = 1500;
  sigma[1][1] = -2500;
  sigma[0][1] = 300;

  print("Phi_1000(1500, -2500, 300), expected 1000 -1000 300",
        truncate(sigma, 1000.));

  const DamageTruncatedLaw<2> paper(1000.);
  print("paper law, zeta = 1, expected 0 0 0", paper.rate(sigma, {}, 1.));
  print("paper law, zeta = 0, expected -1000 1000 -300",
        paper.rate(sigma, {}, 0.));
  print("paper law, zeta = 0.25, expected -750 750 -225",
        paper.rate(sigma, {}, 0.25));

  const MaxwellLaw<2> maxwell(0.5, std::numeric_limits<double>::infinity());
  print("Maxwell eta = 0.5, expected -3000 5000 -600",
        maxwell.rate(sigma, {}, 1.));
  const MaxwellLaw<2> truncated(0.5, 1000.);
  print("truncated Maxwell, expected -2000 2000 -600",
        truncated.rate(sigma, {}, 1.));

  std::cout << "step limits: Maxwell " << maxwell.explicit_step_limit()
            << " (expected 1), paper " << paper.explicit_step_limit()
            << " (expected 2), none "
            << NoViscoplasticity<2>().explicit_step_limit() << " (expected inf)"
            << std::endl;
  std::cout << "none is zero: " << NoViscoplasticity<2>().is_zero()
            << ", Maxwell is zero: " << maxwell.is_zero() << std::endl;
}
