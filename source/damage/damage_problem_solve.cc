// The damage obstacle problem of a step: the primal-dual active set of the
// bounds 0 <= zeta <= 1 around the linear solves of DamageSystem (or SNES VI
// whole), storing zeta_n, the damage statistics and the checkpointed state.
#include <vpcontact/damage/damage_problem.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/finite_values.h>
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace VPContact
{
  template <int dim>
  void
  DamageProblem<dim>::solve_step(const unsigned int          n,
                                 const LA::MPI::BlockVector &solution_owned,
                                 const StressHistory<dim>   &history)
  {
    // zeta_{n-1} from the solution and the load b of this step. A source
    // that evaluates to NaN or infinity anywhere spoils the whole load; say
    // so here rather than let CG fail on it. zeta_n is left in damage_owned
    // (and damage): store() puts it into the solution after the stress
    // update, which still reads zeta_{n-1}.
    last_iterations = 0;
    change          = 0.;
    copy_owned_values(solution_owned.block(1), old_damage);
    damage_exchange.copy(old_damage, damage);
    assemble_load(history);
    model.check_source_finite(all_finite(load, communicator), n, time.time(n));
    if (system.solves_obstacle_whole())
      {
        TimerOutput::Scope t(timer, "Damage solve");
        copy_owned_values(old_damage, damage_owned);
        last_iterations
          = system.solve_obstacle(load,
                                  damage_owned,
                                  linear_solver.tolerance(),
                                  model.max_iterations(),
                                  linear_solver.iteration_limit());
        damage_exchange.copy(damage_owned, damage);
        return;
      }
    solve_by_active_set(n);
  }



  template <int dim>
  void
  DamageProblem<dim>::solve_by_active_set(const unsigned int n)
  {
    // The primal-dual active set for 0 <= zeta <= 1: solve with the nodes
    // of the active sets at their bound, recompute the multipliers from the
    // residual, take the next sets, until no node changes. The unknown of
    // the linear solves is the change zeta - zeta_{n-1}: its right-hand
    // side b - K zeta_{n-1} is small where little happens, so the relative
    // tolerance of CG measures what changes, not the mass term
    // M zeta_{n-1}/k. First the fast search (see find_sets_fast()); should
    // it not settle, the plain method from the sets of the previous step,
    // every solve to the Solver tolerance.
    LA::MPI::Vector step_rhs(old_damage);
    system.vmult_on_support(step_rhs, old_damage);
    step_rhs.sadd(-1., 1., load);
    bounds.begin_step(system.support());
    system.begin_step();
    const std::vector<BoundStatus> previous_sets = bounds.sets();
    if (!find_sets_fast(step_rhs))
      {
        bounds.restore_sets(previous_sets);
        change = 0.;
        for (unsigned int iteration = 1;; ++iteration)
          {
            ++last_iterations;
            const unsigned int n_changed
              = solve_with_sets(step_rhs, linear_solver.tolerance());
            if (n_changed == 0)
              break;
            AssertThrow(
              iteration < model.max_iterations(),
              ExcMessage(
                "Step " + std::to_string(n)
                + ": the active set of the damage bounds did not converge: "
                  "after "
                + std::to_string(iteration) + " iterations "
                + std::to_string(n_changed)
                + " node(s) still change set. Raise Damage/Maximum active set "
                  "iterations = "
                + std::to_string(model.max_iterations())
                + "; on strongly stretched cells (aspect ratio above about "
                  "1.4) the lumped matrix is not an M-matrix and the "
                  "iteration need not be monotone, and with a loose "
                  "Solver/Relative tolerance (1e-10 is the default) the "
                  "multipliers are too inexact to "
                  "decide the sets. The output up to step "
                + std::to_string(n - 1) + " is complete in " + output_directory
                + "."));
          }
      }
    rings_ahead = static_cast<unsigned int>(std::floor(bounds.rings_moved()));
  }



  template <int dim>
  bool
  DamageProblem<dim>::find_sets_fast(const LA::MPI::Vector &step_rhs)
  {
    // The first sets: one semismooth Newton step from zeta_{n-1} with the
    // multipliers of this step's load, b - K zeta_{n-1}. It starts from the
    // sets of the previous step and already moves the nodes that this load
    // alone pushes off (or onto) a bound; without it the first solve would
    // only find them.
    residual_exchange.copy(step_rhs, residual);
    bounds.update(residual, damage, time.step_size());

    // Then the front of the upper set is moved ahead by as many whole rings
    // as it moved in the previous step (see
    // DamageBounds::free_ahead_of_front()), which saves solves on fine
    // meshes, where the front moves by several rings in a step.
    bounds.free_ahead_of_front(system.support(), rings_ahead);

    // From here on the passes between the solves visit the nodes the solves
    // can change (see DamageWorkSet), where the solver takes the free set
    // as a list and those nodes are few enough to pay for the set.
    const bool on_work_set
      = system.solves_on_free_nodes() && start_work_set(step_rhs);

    // While the sets still change, the solves that find them need not be
    // exact: their multipliers only decide the next sets. The first few
    // stop at a relative residual of 1e-4 (or the Solver tolerance, if
    // looser). A node whose multiplier is within that error of its test may
    // land in the wrong set, and a later solve moves it back; on the paper
    // scene this costs a few more solves in a run but fewer CG iterations
    // than two more digits in every solve would (the damage solve phase of
    // scripts/bench). Once the sets are (nearly) stable, solves to the
    // Solver tolerance must confirm them, so the sets are always decided by
    // an exact solve. "Nearly": when a solve changed at most a few nodes,
    // the next one is exact at once, since its correction is local. Inexact
    // multipliers can make two nodes trade places for ever, so after six
    // iterations every solve is exact, and after twenty the caller starts
    // again from the previous step's sets.
    constexpr unsigned int few   = 10;
    const double           tight = linear_solver.tolerance();
    const double           loose = std::max(tight, 1e-4);
    bool                   exact = false;
    for (unsigned int iteration = 1; iteration <= 20; ++iteration)
      {
        const double tolerance = (exact || iteration > 6 ? tight : loose);
        ++last_iterations;
        const unsigned int n_changed
          = (on_work_set ? solve_on_work_set(step_rhs, tolerance) :
                           solve_with_sets(step_rhs, tolerance));
        if (n_changed == 0 && tolerance == tight)
          return true;
        exact = (n_changed <= few);
      }
    return false;
  }



  template <int dim>
  unsigned int
  DamageProblem<dim>::solve_with_sets(const LA::MPI::Vector &step_rhs,
                                      const double           tolerance)
  {
    TimerOutput::Scope t(timer, "Damage solve");

    // The held nodes: hanging nodes (change 0 in the solve, set from their
    // parents after it) and the nodes at a bound (their change is
    // prescribed).
    held         = system.hanging_node_positions();
    bound_change = 0.;
    bounds.held_changes(old_damage, held, bound_change);

    // The free nodes solve K_FF change_F = (b - K (zeta_{n-1} +
    // bound_change))_F; the held rows of the right-hand side are zero. The
    // change of the previous solve is the start vector.
    system.vmult_on_support(solve_rhs, bound_change);
    solve_rhs.sadd(-1., 1., step_rhs);
    for (const auto i : held)
      {
        solve_rhs.begin()[i] = 0.;
        change.begin()[i]    = 0.;
      }
    system.solve(solve_rhs,
                 change,
                 held,
                 tolerance,
                 linear_solver.iteration_limit());
    change += bound_change;
    system.distribute_hanging_nodes(change);
    copy_owned_values(old_damage, damage_owned);
    damage_owned += change;
    damage_exchange.copy(damage_owned, damage);

    // The multipliers r = b - K zeta = (b - K zeta_{n-1}) - K change
    // (bounds not condensed; hanging nodes carry none) and the next sets.
    system.vmult_on_support(residual_owned, change);
    residual_owned.sadd(-1., 1., step_rhs);
    residual_exchange.copy(residual_owned, residual);
    return bounds.update(residual, damage, time.step_size());
  }



  template <int dim>
  bool
  DamageProblem<dim>::start_work_set(const LA::MPI::Vector &step_rhs)
  {
    // Where a quarter of the nodes or more move (a damage spread over much
    // of the body), the set would hold most of them with their rings, and
    // passes through its list cost more than the plain passes over all
    // nodes, besides the set's own building: the step keeps those. All
    // ranks take the same path.
    const std::vector<unsigned int> moving
      = bounds.moving_positions(old_damage);
    const unsigned int n_owned = damage_owned.locally_owned_size();
    if (4
          * Utilities::MPI::sum<types::global_dof_index>(moving.size(),
                                                         communicator)
        >= Utilities::MPI::sum<types::global_dof_index>(n_owned, communicator))
      return false;

    // Outside the work set the vectors the solves write hold what they
    // would hold after a solve over all nodes: no change, zeta_{n-1}, and
    // the residual b - K zeta_{n-1} (the ghosted damage and residual
    // already do, from solve_step() and the first decision).
    copy_owned_values(old_damage, damage_owned);
    copy_owned_values(step_rhs, residual_owned);
    bound_change  = 0.;
    serial_layout = (Utilities::MPI::n_mpi_processes(communicator) == 1);
    AssertThrow(!serial_layout
                  || static_cast<std::size_t>(
                       damage.trilinos_vector().Map().NumMyElements())
                       == n_owned,
                ExcInternalError());
    const SupportProduct &product = system.support();
    work.clear(n_owned);
    work.add_neighbourhoods(moving, product);
    work.add_neighbourhoods(system.hanging_node_positions(), product);
    work.add(product.rows_of_ghosts());
    return true;
  }



  template <int dim>
  unsigned int
  DamageProblem<dim>::solve_on_work_set(const LA::MPI::Vector &step_rhs,
                                        const double           tolerance)
  {
    TimerOutput::Scope t(timer, "Damage solve");

    // solve_with_sets() on the positions of the work set: the same values
    // there, in the same order, and none changes elsewhere.
    const std::vector<unsigned int> &rows = work.positions();
    held.clear();
    free_positions.clear();
    bounds.held_changes_on(rows,
                           old_damage,
                           bound_change,
                           held,
                           free_positions);
    system.vmult_on_rows(solve_rhs, bound_change, rows);
    const double *const step_values = step_rhs.begin();
    double *const       rhs         = solve_rhs.begin();
    double *const       delta       = change.begin();
    for (const unsigned int i : rows)
      rhs[i] = step_values[i] - rhs[i];
    for (const unsigned int i : held)
      rhs[i] = delta[i] = 0.;
    system.solve_free(solve_rhs,
                      change,
                      free_positions,
                      tolerance,
                      linear_solver.iteration_limit());
    const double *const bound_values = bound_change.begin();
    for (const unsigned int i : rows)
      delta[i] += bound_values[i];
    system.distribute_hanging_nodes(change);
    const double *const old_values = old_damage.begin();
    double *const       zeta       = damage_owned.begin();
    for (const unsigned int i : rows)
      zeta[i] = old_values[i] + delta[i];
    copy_on_work_set(damage_owned, damage_exchange, damage);

    system.vmult_on_rows(residual_owned, change, rows);
    double *const multiplier = residual_owned.begin();
    for (const unsigned int i : rows)
      multiplier[i] = step_values[i] - multiplier[i];
    copy_on_work_set(residual_owned, residual_exchange, residual);
    const unsigned int n_changed = bounds.update_on(rows,
                                                    residual,
                                                    damage,
                                                    time.step_size(),
                                                    changed_positions);
    work.add_neighbourhoods(changed_positions, system.support());
    return n_changed;
  }



  template <int dim>
  void
  DamageProblem<dim>::copy_on_work_set(const LA::MPI::Vector &owned,
                                       GhostExchange         &exchange,
                                       LA::MPI::Vector       &ghosted) const
  {
    // On one rank the ghosted vector has the owned layout; on several its
    // ghosts come from the other ranks, through the whole exchange.
    if (!serial_layout)
      {
        exchange.copy(owned, ghosted);
        return;
      }
    const double *const from = owned.begin();
    double *const       to   = ghosted.begin();
    for (const unsigned int i : work.positions())
      to[i] = from[i];
  }



  template <int dim>
  void
  DamageProblem<dim>::store(const unsigned int    n,
                            LA::MPI::BlockVector &solution_owned)
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
    clip = Utilities::MPI::max(clip, communicator);
    AssertThrow(std::isfinite(clip),
                ExcMessage("Step " + std::to_string(n)
                           + ": the damage is not finite. The output up to the "
                             "previous step is complete in "
                           + output_directory + "."));
    // Hanging nodes take the average of their (clipped) parents again.
    system.distribute_hanging_nodes(damage_owned);
    last_clip = clip;
    damage_exchange.copy(damage_owned, damage);
    copy_owned_values(damage_owned, solution_owned.block(1));
  }



  template <int dim>
  void
  DamageProblem<dim>::add_statistics(Statistics           &statistics,
                                     std::string          &line,
                                     const StepQuantities &quantities)
  {
    const double fraction = quantities.damaged_fraction;
    // Nodal extremes, the bound violation (which must be exactly 0), and the
    // volume fraction where zeta < 1 at the quadrature points. On a uniform
    // mesh the fraction is a multiple of the weight of a point and often
    // lands on a tie of the rounding to 0.01 %, which the order of the sums
    // would decide: it is first rounded to 1e-9.
    const auto [lowest, highest] = range(damage_owned);
    const double violation       = std::max({0., -lowest, highest - 1.});
    largest_violation            = std::max(largest_violation, violation);

    statistics.add_value("damage_min", lowest);
    statistics.add_value("damage_max", highest);
    statistics.add_value("damaged_fraction", fraction);
    statistics.add_value("damage_bound_violation", violation);
    statistics.add_value("damage_clip", last_clip);
    statistics.add_value("damage_iterations", last_iterations);
    line += "  zeta in [" + to_text(std::round(lowest * 1e6) / 1e6) + ", "
            + to_text(std::round(highest * 1e6) / 1e6) + "]  damaged "
            + to_text(std::round(std::round(fraction * 1e9) / 1e5) / 1e2) + "%";
  }



  template <int dim>
  double
  DamageProblem<dim>::max_violation() const
  {
    return largest_violation;
  }



  template <int dim>
  std::string
  DamageProblem<dim>::violation_summary() const
  {
    std::ostringstream text;
    text << "Damage bounds 0 <= zeta <= 1 at every node and step: largest "
            "violation "
         << largest_violation
         << " (exactly 0: " << (largest_violation == 0. ? "yes" : "NO")
         << ")\n";
    return text.str();
  }



  template <int dim>
  std::string
  DamageProblem<dim>::work_summary() const
  {
    // The solves' reductions make every rank wait for the busiest one, so
    // their time follows the largest work, not the mean: on p ranks they
    // run at most p * mean / largest times as fast as on one rank of the
    // same speed. The damage lies where the body is strained most, often
    // on few of the ranks that the mesh's partition gives equal cells.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const auto         work
      = Utilities::MPI::min_max_avg(system.solve_work(), communicator);
    if (!(work.max > 0.))
      return "";
    std::ostringstream text;
    // On one rank the sum alone: against it, the sum on several ranks
    // shows the iterations that block Jacobi between the ranks adds.
    if (n_ranks == 1)
      {
        text << "Damage solves, free nodes times CG iterations: "
             << printf_text("%.3e", work.sum) << "\n";
        return text.str();
      }
    text << "Damage solves, free nodes times CG iterations per rank: largest "
         << printf_text("%.3e", work.max) << " on rank " << work.max_index
         << ", mean " << printf_text("%.3e", work.avg) << " (largest / mean "
         << printf_text("%.3g", work.max / work.avg) << "): on these "
         << n_ranks << " ranks they can run at most "
         << printf_text("%.3g", work.sum / work.max)
         << " times as fast as on one\n";
    return text.str();
  }



  template <int dim>
  std::optional<ScalarNodeSpace<dim>>
  DamageProblem<dim>::node_space() const
  {
    ScalarNodeSpace<dim> space;
    space.owned       = system.owned();
    space.relevant    = system.relevant();
    space.constraints = &system.hanging_node_constraints();
    space.cell_nodes  = [this](const auto &cell, auto &indices) {
      system.dof_indices(cell, indices);
    };
    return space;
  }



  template <int dim>
  void
  DamageProblem<dim>::write_checkpoint(
    LA::MPI::Vector               &sets_owned,
    std::map<std::string, double> &counters) const
  {
    LA::MPI::Vector bound_sets(system.owned(), communicator);
    bounds.write_state(bound_sets);
    system.scatter(bound_sets, sets_owned);
    counters["max_damage_violation"] = largest_violation;
    counters["damage_rings_ahead"]   = rings_ahead;
  }



  template <int dim>
  void
  DamageProblem<dim>::read_checkpoint(
    const LA::MPI::Vector &sets_owned,
    const LA::MPI::Vector & /*sets*/,
    const std::function<double(const std::string &)> &counter)
  {
    read_state(sets_owned, counter, false);
  }



  template <int dim>
  void
  DamageProblem<dim>::read_transferred_state(
    const LA::MPI::Vector &sets_owned,
    const LA::MPI::Vector & /*sets*/,
    const std::function<double(const std::string &)> &counter)
  {
    read_state(sets_owned, counter, true);
  }



  template <int dim>
  void
  DamageProblem<dim>::read_state(
    const LA::MPI::Vector                            &sets_owned,
    const std::function<double(const std::string &)> &counter,
    const bool                                        interpolated)
  {
    LA::MPI::Vector bound_sets(system.owned(), communicator);
    system.gather(sets_owned, bound_sets);
    LA::MPI::Vector ghosted(system.owned(), system.relevant(), communicator);
    ghosted = bound_sets;
    bounds.read_state(ghosted, interpolated);
    largest_violation = counter("max_damage_violation");
    rings_ahead = static_cast<unsigned int>(counter("damage_rings_ahead"));
  }



  template class DamageProblem<2>;
  template class DamageProblem<3>;
} // namespace VPContact
