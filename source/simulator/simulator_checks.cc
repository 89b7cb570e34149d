// The simulator's checks of the input that involve more than one section:
// the stability of the explicit step, what a mesh of triangles (tetrahedra)
// cannot do, and a body that the slipping contact no longer holds.
#include <vpcontact/input/input_error.h>
#include <vpcontact/simulator/simulator.h>

#include <cmath>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::check_stability_limits() const
  {
    // The forward Euler step of sigma_dot = G(sigma) amplifies an error by
    // 1 - k L_G for a law with Lipschitz constant L_G; beyond k = 2 / L_G it
    // grows without bound. Refuse such a step before computing anything.
    if (viscoplasticity.implicit())
      return; // backward Euler is stable for any step
    const double k     = time_discretization.step_size();
    const double limit = viscoplastic_law->explicit_step_limit();
    VPContactCheckParameter(
      k <= limit,
      "Time/Time step",
      k,
      "the explicit (forward Euler) viscoplastic step is unstable for this "
      "law ("
        + viscoplastic_law->description() + ") when k > " + to_text(limit)
        + " (2 / Lipschitz constant of G; for Maxwell 2 eta). "
          "Choose Time step <= "
        + to_text(limit)
        + ", a slower law (larger Viscoplasticity/Relaxation time), or "
          "Viscoplasticity/Time integration = implicit.");
  }



  template <int dim>
  void
  Simulator<dim>::check_simplex_support() const
  {
    // What a mesh of triangles (tetrahedra) cannot do, refused before the
    // first step: deal.II 9.4 refines simplices only uniformly, the
    // reference snapshots interpolate Q1 fields, and checkpoints are
    // p4est's, which holds only quadrilaterals (hexahedra).
    if (!discretization.simplex())
      return;
    const std::string cells = (dim == 2 ? "triangles" : "tetrahedra");
    const std::string other = (dim == 2 ? "quadrilaterals" : "hexahedra");
    VPContactCheckParameter(
      !convergence_study.refinement().needs_indicators(),
      "Mesh refinement/Strategy",
      "adaptive",
      "adaptive cycles need hanging nodes, which deal.II 9.4 does not make "
      "on "
        + cells + ". Use Strategy = uniform, or a mesh of " + other + ".");
    const auto &reference = convergence_study.reference();
    VPContactCheckParameter(
      !reference.writes_snapshots() && !reference.compares(),
      reference.writes_snapshots() ? "Reference solution/Write snapshots" :
                                     "Reference solution/Compare with",
      reference.writes_snapshots() ? "true" : "(a folder)",
      "snapshots hold Q1 fields on " + other + "; on " + cells
        + " compare runs through Output/Monitor points and statistics.csv.");
    VPContactCheckParameter(
      !checkpointing.writes_periodically() && !checkpointing.resume(),
      checkpointing.resume() ? "Checkpoint/Resume from checkpoint" :
                               "Checkpoint/Every steps or Every seconds",
      checkpointing.resume() ? "true" : "not 0",
      "checkpoints are written by p4est, which holds only " + other
        + ". Set Checkpoint/Every steps = 0, Every seconds = 0 and Resume "
          "from checkpoint = false on a mesh of "
        + cells + ".");
  }



  template <int dim>
  void
  Simulator<dim>::check_held_while_slipping(const double time) const
  {
    // With no stick node left, the contact boundary holds the body only in
    // its normal direction, and the friction force g on it is fixed: a
    // rigid motion that the other constraints leave free is then free in
    // the next solve too, whose matrix is singular and whose answer, if
    // any, is a body that slides away. Stop before it, saying why.
    const std::string &motion = friction_problem->motion_free_when_all_slip();
    if (motion.empty() || friction_problem->n_stick_nodes() > 0)
      return;
    const double k = time_discretization.step_size();
    AssertThrow(
      false,
      ExcMessage(
        "At t = " + to_text(time) + " (step "
        + std::to_string(static_cast<long>(std::lround(time / k)))
        + ") every contact node slips: the friction bound "
          "(Contact/Friction bound, at most "
        + to_text(friction_problem->max_bound())
        + " here) no longer holds the tangential load on the contact "
          "boundary, and nothing else holds the body against "
        + motion + " (Boundary conditions: " + boundary_conditions.summary()
        + "). The body would slide away without bound, and the "
          "quasistatic problem has no solution from here on. Raise "
          "Contact/Friction bound, or hold the body against this motion "
          "with a boundary of Boundary conditions/Clamped boundary ids, "
          "Roller boundary ids or Prescribed displacement boundary ids. "
          "The output up to the previous step is complete in "
        + output_writer.directory() + "."));
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
