// Unit test: the primal-dual active set decision for Tresca friction,
// against the cases that define it (lambda = -sigma_tau, w the tangential
// slip, c > 0): |lambda + c w| <= g sticks; otherwise the node slips in the
// direction n of lambda + c w, with the slip stiffness
// beta = g c / (|lambda + c w| - g) of the linearised law
// lambda = g n + beta (I - n n^T) w. On a line (one tangent direction) this
// is the sign switch lambda = g sign(w); in the tangent plane of a 3D
// contact surface it is the ball |lambda| <= g.
// Last, c itself: factor E / h with the node's size h (its boundary
// length in 2D, the square root of its boundary area in 3D).
#include <vpcontact/contact/tresca_friction.h>

#include <iostream>

using namespace VPContact;

template <int dim>
void
show(const Tensor<1, dim> &lambda,
     const Tensor<1, dim> &w,
     const double          g,
     const double          c)
{
  const auto d = tresca_decision(lambda, w, g, c);
  std::cout << "lambda = (" << lambda << "), w = (" << w << "), g = " << g
            << ", c = " << c << ": "
            << (d.status == ContactStatus::stick ? "stick" : "slip");
  if (d.status == ContactStatus::slip)
    std::cout << ", n = (" << d.direction << "), beta = " << d.slip_stiffness;
  std::cout << std::endl;
}

void
show(const double lambda, const double w, const double g, const double c)
{
  show(Tensor<1, 1>({lambda}), Tensor<1, 1>({w}), g, c);
}

int
main()
{
  // One tangent direction.
  show(5, 0, 10, 1);     // below the bound, not moving: stick
  show(10, 0, 10, 1);    // at the bound, not moving: stick
  show(12, 0, 10, 1);    // above the bound: slip in its direction, beta 5
  show(-12, 0, 10, 1);   // the same, other direction
  show(10, 1e-3, 10, 1); // at the bound and moving forward: slip +
  show(10, -1, 10, 1);   // moving against the traction: 10 - 1 = 9, stick
  show(-10, -1, 10, 50); // at the bound, moving backward: slip -
  show(0, 0, 0, 1);      // g = 0, at rest: stick (|0| <= 0)
  show(1e-9, 0, 0, 1);   // g = 0, any traction: slip

  // The tangent plane of a 3D surface: the ball |lambda| <= 5.
  show(Tensor<1, 3>({3, 4, 0}), Tensor<1, 3>(), 5, 1); // on the ball: stick
  show(Tensor<1, 3>({6, 8, 0}), Tensor<1, 3>(), 5, 1); // n = (.6, .8), beta 1
  // At the bound, slipping along lambda: n = w / |w|, beta = g / |w| = 50.
  show(Tensor<1, 3>({0, 3, 4}), Tensor<1, 3>({0, 0.06, 0.08}), 5, 1);
  // Slip across the traction turns n towards w: z = (0, 3, 4) + (0.1, 0, 0).
  show(Tensor<1, 3>({0, 3, 4}), Tensor<1, 3>({0.1, 0, 0}), 5, 1);
  // Inside the ball but moving: |(1, 0, 0) + 10 (0.5, 0, 0)| = 6 > 5: slip.
  show(Tensor<1, 3>({1, 0, 0}), Tensor<1, 3>({0.5, 0, 0}), 5, 10);

  // c = factor E / h with the node's size h: a 2D node of boundary length
  // 0.1 and a 3D node of boundary area 0.01 both have h = 0.1, so c = 10 E;
  // a 3D node of a 72^3 mesh (area 1/72^2) has h = 1/72.
  std::cout << "c (2D, m = 0.1, E = 1000) = "
            << complementarity_constant<2>(1, 1000, 0.1) << std::endl;
  std::cout << "c (3D, m = 0.01, E = 1000) = "
            << complementarity_constant<3>(1, 1000, 0.01) << std::endl;
  std::cout << "c (3D, m = 1/72^2, E = 1000, factor 0.5) = "
            << complementarity_constant<3>(0.5, 1000, 1. / (72 * 72))
            << std::endl;
}
