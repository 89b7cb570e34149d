// The section "Solver" entry for the start vector of the displacement
// solve, and its extrapolation in time.
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/simulator/increment_predictor.h>

#include <algorithm>

namespace VPContact
{
  void
  IncrementPredictor::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry(
      "Start vector extrapolation degree",
      "2",
      Patterns::Integer(0, 2),
      "The start vector of a step's displacement solve is the polynomial of "
      "this degree through the increments of the last steps, evaluated at "
      "the new step: 0 is the previous increment, 1 the linear and 2 the "
      "quadratic extrapolation. It changes the CG iteration count, not the "
      "solution; the quadratic one needs the fewest iterations on smooth "
      "loadings. An increment more than ten times larger or smaller than "
      "the last (the first step from u_0 = 0 under a load) restarts the "
      "history from it.");
    prm.leave_subsection();
  }



  void
  IncrementPredictor::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    degree = prm.get_integer("Start vector extrapolation degree");
    prm.leave_subsection();
  }



  void
  IncrementPredictor::reinit(const IndexSet &locally_owned_dofs,
                             const MPI_Comm  communicator)
  {
    for (auto &w : history)
      w.reinit(locally_owned_dofs, communicator);
    n_valid = 0;
  }



  void
  IncrementPredictor::predict(LA::MPI::Vector &increment) const
  {
    // The extrapolation weights for equal steps: the polynomial through
    // (n-1, w_{n-1}), (n-2, w_{n-2}), ... evaluated at n.
    const unsigned int p = std::min(degree, n_valid > 0 ? n_valid - 1 : 0u);
    if (p == 1)
      {
        increment = history[0];
        increment.sadd(2., -1., history[1]);
      }
    else if (p == 2)
      {
        increment = history[2];
        increment.add(3., history[0], -3., history[1]);
      }
  }



  void
  IncrementPredictor::record(const LA::MPI::Vector &increment)
  {
    if (degree == 0)
      return;
    // An increment more than ten times larger or smaller than the last is
    // a jump, not a point of a smooth curve: the first step from the
    // paper's u_0 = 0 under a load that is not zero at t = 0 reaches
    // equilibrium in one step, and the next increments are about a
    // hundredth of it. The history then restarts from the new increment
    // alone. The rule reads only the recorded vectors, so a run resumed
    // from a checkpoint applies it alike.
    if (n_valid > 0)
      {
        const double size = increment.l2_norm();
        const double last = history[0].l2_norm();
        if (!(size <= jump_ratio * last && last <= jump_ratio * size))
          n_valid = 0;
      }
    // Shift the history by swapping the vectors, not copying them.
    history[2].swap(history[1]);
    history[1].swap(history[0]);
    history[0] = increment;
    n_valid    = std::min(n_valid + 1, 3u);
  }



  unsigned int
  IncrementPredictor::n_recorded() const
  {
    return n_valid;
  }



  LA::MPI::Vector &
  IncrementPredictor::recorded(const unsigned int i)
  {
    return history[i];
  }



  void
  IncrementPredictor::set_n_recorded(const unsigned int n)
  {
    n_valid = std::min(n, 3u);
  }
} // namespace VPContact
