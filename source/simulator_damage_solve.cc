// The simulator's damage obstacle problem, step 4 of the scheme: the
// primal-dual active set of the bounds 0 <= zeta <= 1 around the linear
// solves of DamageSystem, storing zeta_n, and the damage statistics.
#include <vpcontact/finite_values.h>
#include <vpcontact/input_error.h>
#include <vpcontact/simulator.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::solve_damage(const unsigned int n)
  {
    // The primal-dual active set for 0 <= zeta <= 1: solve with the nodes
    // of the active sets at their bound, recompute the multipliers from the
    // residual, take the next sets, until no node changes. The unknown of
    // the linear solves is the change zeta - zeta_{n-1}: its right-hand
    // side F - kappa A zeta_{n-1} is small where little happens, so the
    // relative tolerance of CG measures what changes, not the mass term
    // M zeta_{n-1}/k. zeta_n is left in damage_owned (and damage):
    // store_damage() puts it into the solution after the stress update.
    // This function reads of the displacement step only the damage source
    // and the solution (zeta_{n-1}), and writes only the damage vectors.
    last_damage_iterations                  = 0;
    damage_change                           = 0.;
    const TrilinosWrappers::SparseMatrix &K = damage_system.matrix();

    // zeta_{n-1} from the solution, b and b - K zeta_{n-1} of this step.
    damage_system.gather(solution_owned, damage_old);
    damage = damage_old;
    assemble_damage(false);
    // A source that evaluates to NaN or infinity anywhere spoils the whole
    // load; say so here rather than let CG fail on it.
    damage_model.check_source_finite(all_finite(damage_load, mpi_communicator),
                                     n,
                                     time_discretization.time(n));
    if (damage_system.solves_obstacle_whole())
      {
        TimerOutput::Scope t(computing_timer, "Damage solve");
        damage_owned = damage_old;
        last_damage_iterations
          = damage_system.solve_obstacle(damage_load,
                                         damage_owned,
                                         linear_solver.tolerance(),
                                         damage_model.max_iterations(),
                                         linear_solver.iteration_limit());
        damage = damage_owned;
        return;
      }
    TrilinosWrappers::MPI::Vector step_rhs(damage_old);
    K.vmult(step_rhs, damage_old);
    step_rhs.sadd(-1., 1., damage_load);

    // First the fast search (see find_damage_sets_fast()); should it not
    // settle, the plain primal-dual active set method from the sets of the
    // previous step, every solve to the Solver tolerance.
    damage_bounds.begin_step(K);
    const std::vector<BoundStatus> previous_sets = damage_bounds.sets();
    if (!find_damage_sets_fast(step_rhs))
      {
        damage_bounds.restore_sets(previous_sets);
        damage_change = 0.;
        for (unsigned int iteration = 1;; ++iteration)
          {
            ++last_damage_iterations;
            const unsigned int n_changed
              = solve_damage_with_sets(step_rhs, linear_solver.tolerance());
            if (n_changed == 0)
              break;
            AssertThrow(
              iteration < damage_model.max_iterations(),
              ExcMessage(
                "Step " + std::to_string(n)
                + ": the active set of the damage bounds did not "
                  "converge: after "
                + std::to_string(iteration) + " iterations "
                + std::to_string(n_changed)
                + " node(s) still change set. Raise Damage/Maximum "
                  "active set iterations = "
                + std::to_string(damage_model.max_iterations())
                + "; on strongly stretched cells (aspect ratio above "
                  "about 1.4) the lumped matrix is not an M-matrix and "
                  "the iteration need not be monotone, and with a loose "
                  "Solver/Relative tolerance (1e-6 did this at 512^2 "
                  "cells; 1e-10 is the default) the multipliers are too "
                  "inexact to decide the sets. The output up to "
                  "step "
                + std::to_string(n - 1) + " is complete in "
                + output_writer.directory() + "."));
          }
      }

    damage_rings_ahead
      = static_cast<unsigned int>(std::floor(damage_bounds.rings_moved()));
  }



  template <int dim>
  bool
  Simulator<dim>::find_damage_sets_fast(
    const TrilinosWrappers::MPI::Vector &step_rhs)
  {
    // The first sets: one semismooth Newton step from zeta_{n-1} with the
    // multipliers of this step's load, b - K zeta_{n-1}. It starts from the
    // sets of the previous step and already moves the nodes that this load
    // alone pushes off (or onto) a bound; without it the first solve would
    // only find them.
    damage_residual = step_rhs;
    damage_bounds.update(damage_residual,
                         damage,
                         time_discretization.step_size());

    // Then the front of the upper set is moved ahead by as many whole rings
    // as it moved in the previous step (see
    // DamageBounds::free_ahead_of_front()), which saves solves on fine
    // meshes, where the front moves by several rings in a step.
    damage_bounds.free_ahead_of_front(damage_system.matrix(),
                                      damage_rings_ahead);

    // While the sets still change, the solves that find them need not be
    // exact: their multipliers only decide the next sets. The first few
    // stop at a relative residual of 1e-6 (or the Solver tolerance, if
    // looser); once the sets are (nearly) stable, solves to the Solver
    // tolerance must confirm them, so the sets are always decided by an
    // exact solve. "Nearly": when a solve changed at most a few nodes, the
    // next one is exact at once. Its correction is local, so the inexact
    // solve that would only confirm the sets before the exact one costs a
    // solve's fixed work for little (fewer damage solves, the same printed
    // results; see git log). Inexact multipliers can
    // make two nodes trade places for ever (seen at 512^2 cells when zeta first
    // reaches 0), so after six iterations every solve is exact, and after
    // twenty the caller starts again from the previous step's sets.
    constexpr unsigned int few   = 10;
    const double           tight = linear_solver.tolerance();
    const double           loose = std::max(tight, 1e-6);
    bool                   exact = false;
    for (unsigned int iteration = 1; iteration <= 20; ++iteration)
      {
        const double tolerance = (exact || iteration > 6 ? tight : loose);
        ++last_damage_iterations;
        const unsigned int n_changed
          = solve_damage_with_sets(step_rhs, tolerance);
        if (n_changed == 0 && tolerance == tight)
          return true;
        exact = (n_changed <= few);
      }
    return false;
  }



  template <int dim>
  unsigned int
  Simulator<dim>::solve_damage_with_sets(
    const TrilinosWrappers::MPI::Vector &step_rhs,
    const double                         tolerance)
  {
    TimerOutput::Scope t(computing_timer, "Damage solve");

    // The held nodes: hanging nodes (change 0 in the solve, set from their
    // parents after it) and the nodes at a bound (their change is
    // prescribed). The list and the vector are members: a fresh vector of
    // the size of the mesh in every solve costs its page faults.
    std::vector<unsigned int>     &held         = damage_held;
    TrilinosWrappers::MPI::Vector &bound_change = damage_bound_change;
    held         = damage_system.hanging_node_positions();
    bound_change = 0.;
    damage_bounds.held_changes(damage_old, held, bound_change);

    // The free nodes solve K_FF change_F = (b - K (zeta_{n-1} +
    // bound_change))_F; the held rows of the right-hand side are zero. The
    // change of the previous solve is the start vector.
    damage_system.matrix().vmult(damage_rhs, bound_change);
    damage_rhs.sadd(-1., 1., step_rhs);
    for (const auto i : held)
      {
        damage_rhs.begin()[i]    = 0.;
        damage_change.begin()[i] = 0.;
      }
    damage_system.solve(damage_rhs,
                        damage_change,
                        held,
                        tolerance,
                        linear_solver.iteration_limit());
    damage_change += bound_change;
    damage_system.distribute_hanging_nodes(damage_change);
    damage_owned = damage_old;
    damage_owned += damage_change;
    damage = damage_owned;

    // The multipliers r = b - K zeta = (b - K zeta_{n-1}) - K change
    // (bounds not condensed; hanging nodes carry none) and the next sets.
    damage_system.matrix().vmult(damage_residual_owned, damage_change);
    damage_residual_owned.sadd(-1., 1., step_rhs);
    damage_residual = damage_residual_owned;
    return damage_bounds.update(damage_residual,
                                damage,
                                time_discretization.step_size());
  }



  template <int dim>
  void
  Simulator<dim>::store_damage(const unsigned int n)
  {
    // Nodes between the bounds satisfy them up to the solver tolerance;
    // clip them onto [0, 1] (the exact discrete solution lies there) and
    // record by how much, then store zeta_n in the solution.
    double clip = 0;
    for (double &value : damage_owned)
      {
        const double clipped = std::clamp(value, 0., 1.);
        // NaN compares false: the clip becomes infinite and is caught
        // below, on every rank alike.
        clip  = (std::abs(value - clipped) <= clip ? clip :
                 std::isfinite(value)              ? std::abs(value - clipped) :
                                        std::numeric_limits<double>::infinity());
        value = clipped;
      }
    clip = Utilities::MPI::max(clip, mpi_communicator);
    AssertThrow(std::isfinite(clip),
                ExcMessage("Step " + std::to_string(n)
                           + ": the damage is not finite. The output up to the "
                             "previous step is complete in "
                           + output_writer.directory() + "."));
    // Hanging nodes take the average of their (clipped) parents again.
    damage_system.distribute_hanging_nodes(damage_owned);
    last_damage_clip = clip;
    damage           = damage_owned;
    damage_system.scatter(damage_owned, solution_owned);
    solution = solution_owned;
  }



  template <int dim>
  void
  Simulator<dim>::add_damage_statistics(std::string &line,
                                        const double fraction)
  {
    // Nodal extremes, the bound violation (which must be exactly 0), and the
    // volume fraction where zeta < 1 at the quadrature points (from
    // measure_step()). On a uniform mesh the fraction is a multiple of the
    // weight of a point and often lands on a tie of the rounding to 0.01 %,
    // which the order of the sums would decide: it is first rounded to 1e-9.
    const auto [lowest, highest] = damage_range(damage_owned);
    const double violation       = std::max({0., -lowest, highest - 1.});
    max_damage_violation         = std::max(max_damage_violation, violation);

    statistics.add_value("damage_min", lowest);
    statistics.add_value("damage_max", highest);
    statistics.add_value("damaged_fraction", fraction);
    statistics.add_value("damage_bound_violation", violation);
    statistics.add_value("damage_clip", last_damage_clip);
    statistics.add_value("damage_iterations", last_damage_iterations);
    line += "  zeta in [" + to_text(std::round(lowest * 1e6) / 1e6) + ", "
            + to_text(std::round(highest * 1e6) / 1e6) + "]  damaged "
            + to_text(std::round(std::round(fraction * 1e9) / 1e5) / 1e2) + "%";
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
