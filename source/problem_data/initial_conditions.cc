// The section "Initial state".
#include <vpcontact/problem_data/initial_conditions.h>

namespace VPContact
{
  void
  InitialConditions::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial state");
    {
      prm.declare_entry(
        "Displacement and stress",
        "zero",
        Patterns::Selection("zero|elastic equilibrium"),
        "'zero': u_0 = 0 and sigma_0 = 0, the paper's data; with a load that "
        "is not zero at t = 0 the first step then carries the whole elastic "
        "response. 'elastic equilibrium': u_0 solves the elastic problem "
        "with the load at t = 0 and sigma_0 = E eps(u_0), which satisfies the "
        "compatibility condition (9) of the paper.");
    }
    prm.leave_subsection();
  }



  void
  InitialConditions::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial state");
    equilibrium = (prm.get("Displacement and stress") == "elastic equilibrium");
    prm.leave_subsection();
  }



  bool
  InitialConditions::elastic_equilibrium() const
  {
    return equilibrium;
  }



  std::string
  InitialConditions::description() const
  {
    return equilibrium ? "elastic equilibrium with f(0)" :
                         "zero (u_0 = 0, sigma_0 = 0)";
  }
} // namespace VPContact
