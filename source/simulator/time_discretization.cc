// The section "Time" and the uniform time grid.
#include <vpcontact/input/input_error.h>
#include <vpcontact/simulator/time_discretization.h>

#include <cmath>

namespace VPContact
{
  namespace
  {
    // The most time steps a run may have: far more than a run can afford,
    // and small enough that n k keeps about eight correct digits.
    constexpr double max_steps = 1e8;
  } // namespace



  void
  TimeDiscretization::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    {
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(0),
                        "Final time T [s]. Must be positive.");
      prm.declare_entry("Time step",
                        "0.01",
                        Patterns::Double(0),
                        "Time step k [s]; T must be a whole multiple of k "
                        "(the paper's uniform partition k = T/N).");
    }
    prm.leave_subsection();
  }



  void
  TimeDiscretization::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    T = prm.get_double("End time");
    k = prm.get_double("Time step");
    prm.leave_subsection();

    VPContactCheckParameter(T > 0,
                            "Time/End time",
                            T,
                            "the end time must be positive. Give T > 0 [s].");
    VPContactCheckParameter(k > 0 && k <= T,
                            "Time/Time step",
                            k,
                            "the step must lie in (0, End time = " + to_text(T)
                              + "].");
    // The step count is checked before it is rounded to an integer: a
    // ratio beyond what an unsigned int holds would wrap around silently.
    const double ratio = T / k;
    VPContactCheckParameter(ratio <= max_steps + 0.5,
                            "Time/Time step",
                            k,
                            "T/k = " + to_text(ratio)
                              + " steps is more than this program allows ("
                              + to_text(max_steps)
                              + "). Choose a larger step.");
    // A relative slack of 1e-9 accepts T = 1, k = 0.1 although 1/0.1 is not
    // exactly 10 in binary arithmetic.
    n_total = static_cast<unsigned int>(std::llround(ratio));
    VPContactCheckParameter(
      n_total >= 1 && std::abs(ratio - n_total) <= 1e-9 * ratio,
      "Time/Time step",
      k,
      "End time = " + to_text(T) + " is not a whole number of steps (T/k = "
        + to_text(ratio) + "). Choose k = T/N for an integer N.");
    k_given = k;
    n_given = n_total;
  }



  void
  TimeDiscretization::set_halvings(const unsigned int j)
  {
    AssertThrow(j < 20 && n_given * std::pow(2., j) <= max_steps,
                ExcMessage("Refining the time step " + std::to_string(j)
                           + " times would exceed 1e8 steps. Use fewer "
                             "Mesh refinement/Number of cycles or set Mesh "
                             "refinement/Refine time step with mesh = false."));
    k       = k_given / std::pow(2., j);
    n_total = n_given << j;
  }



  double
  TimeDiscretization::end_time() const
  {
    return T;
  }



  double
  TimeDiscretization::step_size() const
  {
    return k;
  }



  unsigned int
  TimeDiscretization::n_steps() const
  {
    return n_total;
  }



  double
  TimeDiscretization::time(const unsigned int n) const
  {
    return (n == n_total ? T : n * k);
  }
} // namespace VPContact
