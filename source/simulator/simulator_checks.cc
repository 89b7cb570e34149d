// The simulator's check of the input across sections: what a mesh of
// triangles (tetrahedra) cannot do, and when an adapting run estimates.
#include <vpcontact/input/input_error.h>
#include <vpcontact/simulator/simulator.h>

#include <cmath>

namespace VPContact
{
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
      !convergence_study.refinement().adapts_during_run(),
      "Mesh refinement/Adapt during run",
      "true",
      "adapting a mesh needs hanging nodes, which deal.II 9.4 does not make "
      "on "
        + cells + ". Set it to false, or use a mesh of " + other + ".");
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
  Simulator<dim>::check_adaptation_schedule() const
  {
    // An adaptation refines by the indicators of its own step, which must
    // therefore be estimated.
    const auto &refinement = convergence_study.refinement();
    VPContactCheckParameter(
      !refinement.adapts_during_run()
        || error_estimator.estimates_step(refinement.adapt_every(),
                                          refinement.adapt_every() + 1),
      "Mesh refinement/Adapt every",
      refinement.adapt_every(),
      "the mesh adapts by the error indicators of the step it adapts after, "
      "and Error estimate/Every steps does not estimate that step. Make "
      "Adapt every a multiple of Every steps.");
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
