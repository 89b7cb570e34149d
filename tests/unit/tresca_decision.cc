// Unit test: the primal-dual active set decision for Tresca friction,
// against the cases that define it (lambda = -sigma_tau, w the tangential
// slip, c > 0): |lambda + c w| <= g sticks; otherwise the node slips in the
// direction of lambda + c w, so that lambda = g sign(w) on convergence.
#include <vpcontact/tresca_friction.h>

#include <iostream>

using namespace VPContact;

void
show(const double lambda, const double w, const double g, const double c)
{
  const auto d = tresca_decision(lambda, w, g, c);
  std::cout << "lambda = " << lambda << ", w = " << w << ", g = " << g
            << ", c = " << c << ": "
            << (d.status == ContactStatus::stick ? "stick" : "slip")
            << (d.status == ContactStatus::slip ?
                  (d.direction > 0 ? " +" : " -") :
                  "")
            << std::endl;
}

int
main()
{
  show(5, 0, 10, 1);     // below the bound, not moving: stick
  show(10, 0, 10, 1);    // at the bound, not moving: stick
  show(12, 0, 10, 1);    // above the bound: slip in its direction
  show(-12, 0, 10, 1);   // the same, other direction
  show(10, 1e-3, 10, 1); // at the bound and moving forward: slip +
  show(10, -1, 10, 1);   // moving against the traction: 10 - 1 = 9, stick
  show(-10, -1, 10, 50); // at the bound, moving backward: slip -
  show(0, 0, 0, 1);      // g = 0, at rest: stick (|0| <= 0)
  show(1e-9, 0, 0, 1);   // g = 0, any traction: slip
}
