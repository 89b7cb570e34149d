// The initial state (u_0, sigma_0) of a run: the paper's literal zero data, or
// elastic equilibrium with the load at t = 0.
#ifndef vpcontact_initial_conditions_h
#define vpcontact_initial_conditions_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Initial state".
   *
   * 'zero' is the paper's data u_0 = 0, sigma_0 = 0. If the load does not
   * vanish at t = 0, these data violate the compatibility condition (9) and
   * the first step absorbs the instantaneous elastic response (w_1 is of
   * size 1/k); the scheme is still well posed. 'elastic equilibrium' solves
   * the elastic problem with f(0) for u_0 and sets sigma_0 = E eps(u_0),
   * which satisfies (9): use it for convergence studies.
   */
  class InitialConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    bool
    elastic_equilibrium() const;

    std::string
    description() const;

  private:
    bool equilibrium = false;
  };
} // namespace VPContact

#endif
