// The displacement increment of a step: the stick/slip active-set loop
// around the linear solves of the displacement system, the solve itself
// (beside the damage step where the factors allow), and the solve floor.
#include <vpcontact/fe/owned_constraints.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/finite_values.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/simulator/displacement_problem.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <future>

namespace VPContact
{
  template <int dim>
  void
  DisplacementProblem<dim>::initialize_linear_solver(const bool in_background)
  {
    TimerOutput::Scope t(computing_timer, "Build preconditioner");
    // A matrix with an infinite entry makes the factorizations fail deep
    // inside the libraries (ML writes a dump file of it): refuse it here.
    AssertThrow(std::isfinite(displacement.matrix.frobenius_norm()),
                ExcMessage("The stiffness matrix is not finite: Material/"
                           "Young's modulus = "
                           + to_text(material.youngs_modulus())
                           + " overflows with the cell sizes of this mesh. "
                             "Rescale the units of the scene."));
    // The rigid motions are AMG's near null space; a factorization has no
    // use for them. They cost a pass over the cells, so they are computed
    // once per mesh, not at every rebuild after the stick set changes.
    const NearNullSpace none;
    if (!displacement.solver.is_direct()
        && displacement.rigid_motions.modes.empty())
      displacement.rigid_motions = rigid_motions();
    const NearNullSpace &near_null_space
      = (displacement.solver.is_direct() ? none : displacement.rigid_motions);
    if (in_background)
      displacement.solver.initialize_in_background(displacement.matrix,
                                                   near_null_space);
    else
      displacement.solver.initialize(displacement.matrix, near_null_space);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::wait_for_linear_solver()
  {
    // The part of a factorization begun in the background that the work
    // since did not hide counts as building it.
    TimerOutput::Scope t(computing_timer, "Build preconditioner");
    displacement.solver.wait_for_factors();
  }



  template <int dim>
  void
  DisplacementProblem<dim>::begin_increment(const double time,
                                            const bool   with_viscoplastic_rate,
                                            const bool   work_beside)
  {
    if (friction_problem)
      friction_problem->begin_step(time);
    // Prescribed displacements and the gap of unilateral contact give
    // inhomogeneous constraints on du that change from step to step.
    if (boundary_conditions.has_prescribed_displacement()
        || friction.unilateral())
      make_constraints(time, &solution);

    last_linear_iterations = 0;
    kept_one_stick         = false;
    // The first start vector: the increments of the last steps
    // extrapolated (see IncrementPredictor); the active-set iterations of
    // a step then start from the previous iterate.
    if (with_viscoplastic_rate)
      increment_predictor.predict(increment_owned.block(0));
    // With CG, the solves after a change of the sets may stop early (see
    // may_solve_loosely()). The first solve of a step is at the full
    // tolerance where the last step's sets mostly hold; where they cannot
    // (first_solve_turns_directions()), it may stop early too.
    may_loosen  = may_solve_loosely();
    loose_first = may_loosen && first_solve_turns_directions();
    displacement.solver.set_loose_tolerance(loose_first);
    assemble_rhs(time, with_viscoplastic_rate, false);
    if (friction_problem)
      friction_problem->add_slip_forces(constraints, displacement.rhs);
    start_first_solve(work_beside);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::solve_increment(const double time,
                                            const bool   with_viscoplastic_rate)
  {
    begin_increment(time, with_viscoplastic_rate, false);
    finish_increment(time, with_viscoplastic_rate);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::finish_increment(const double time,
                                             const bool with_viscoplastic_rate)
  {
    // Without friction one linear solve. With friction, the primal-dual
    // active set iteration: solve with the current stick and slip sets,
    // recompute the friction multipliers from the residual, take the next
    // sets; stop when no node changes. The sets of the previous step are
    // the start (warm start), and begin_increment() made the first solve.
    // Once the sets stay after a loose solve, the rest of the step solves
    // at the full tolerance until they stay under such a solve too (a
    // loose solve from there would do no CG iteration).
    complete_first_solve();
    bool loose = loose_first;
    for (unsigned int iteration = 1; friction_problem; ++iteration)
      {
        const bool settled = friction_sets_settled(time, iteration);
        if (settled && !loose)
          break;
        may_loosen = may_loosen && !settled;
        loose      = may_loosen;
        displacement.solver.set_loose_tolerance(loose);
        assemble_rhs(time, with_viscoplastic_rate, true);
        friction_problem->add_slip_forces(constraints, displacement.rhs);
        solve_displacement();
      }
    displacement.solver.set_loose_tolerance(false);

    AssertThrow(all_finite(increment_owned.block(0), mpi_communicator),
                ExcMessage("The displacement increment at t = " + to_text(time)
                           + " is not finite. The output up to the previous "
                             "step is complete in "
                           + output_writer.directory() + "."));
    if (with_viscoplastic_rate)
      increment_predictor.record(increment_owned.block(0));
    solution_owned += increment_owned;
    ghosts.copy(solution_owned, solution);
  }



  template <int dim>
  bool
  DisplacementProblem<dim>::may_solve_loosely() const
  {
    // With Tresca friction on a bilateral contact the next sets compare
    // the multipliers with fixed bounds, far above the accuracy of a CG
    // solve to the square root of the tolerance. Coulomb's bounds and the
    // contact set of unilateral contact move with the solution itself;
    // loose solves there keep nodes changing set, so those solve at the
    // full tolerance throughout. A factorization solves exactly anyway.
    return !displacement.solver.is_direct() && !friction.unilateral()
           && friction.friction_law()
                == TrescaFriction<dim>::FrictionLaw::tresca;
  }



  template <int dim>
  bool
  DisplacementProblem<dim>::first_solve_turns_directions() const
  {
    // In 3D the load turns the direction of every slip node a little in
    // every step, by more than Contact/Slip direction tolerance, so the
    // step's first solve is followed by at least one more: on the slip
    // scene at 48^3 cells, the first solve of every later step turns
    // nearly all slip nodes. Its accuracy beyond what decides the next
    // sets would be lost. In 2D a direction only flips, and where no node
    // slips none turns. The sets at the start of the step decide, so that
    // a run resumed from a checkpoint decides alike.
    return friction_problem && dim == 3 && friction_problem->n_slip_nodes() > 0;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::solve_displacement()
  {
    wait_for_linear_solver();
    if (displacement.solver.preconditioner_outdated())
      initialize_linear_solver();
    TimerOutput::Scope t(computing_timer, "Solve");
    stress_ahead.restart();
    last_linear_iterations
      += displacement.solver.solve(increment_owned.block(0), displacement.rhs);
    share_increment();
  }



  template <int dim>
  void
  DisplacementProblem<dim>::start_first_solve(const bool work_beside)
  {
    // With the factors of a Cholesky factorization, the substitutions run
    // in a second thread while the caller does the work beside them, and
    // "Solve" times only the wait for them that the work does not hide.
    // The second thread writes only the increment (and the factors'
    // workspace); the work beside must read neither it nor
    // displacement.rhs, and must not change the linear solver. Other
    // methods, and the factors after the matrix changed in place, solve
    // after the work, in complete_first_solve().
    // Factors or AMG kept through a change of the stick set serve within
    // the step only: a run resumed from a checkpoint of the last step
    // builds them from the matrix of this step's sets, and so must the
    // uninterrupted run, for the two to compute the same bits.
    wait_for_linear_solver();
    if (displacement.solver.preconditioner_outdated()
        || displacement.solver.kept_through_changed_rows())
      initialize_linear_solver();
    if (!work_beside || !displacement.solver.solves_in_background())
      return;
    // After the substitutions the second thread also starts on the stress
    // update (see update_stress_ahead()) while the damage step still runs
    // here: once the damage has spread, the damage step is the longer of
    // the two. CellKinematics checks the increment's layout here (the check
    // may call MPI).
    const double *const increment_entries
      = cell_kinematics.local_entries(increment);
    stress_ahead.restart();
    first_solve = displacement.solver.solve_in_background(
      increment_owned.block(0),
      displacement.rhs,
      [this, increment_entries]() { update_stress_ahead(increment_entries); });
  }



  template <int dim>
  void
  DisplacementProblem<dim>::complete_first_solve()
  {
    if (!first_solve.valid())
      {
        solve_displacement();
        return;
      }
    stress_ahead.arrive();
    TimerOutput::Scope t(computing_timer, "Solve");
    last_linear_iterations += first_solve.get();
  }



  template <int dim>
  void
  DisplacementProblem<dim>::abandon_increment()
  {
    if (!first_solve.valid())
      return;
    stress_ahead.arrive();
    try
      {
        first_solve.get();
      }
    catch (...)
      {
        // The error of the work beside is the one reported.
      }
  }



  template <int dim>
  void
  DisplacementProblem<dim>::share_increment()
  {
    // The solver leaves the constrained entries of the displacement block
    // as they were; they are set from the others.
    distribute_constraints(constraints, increment_owned.block(0));
    ghosts.copy(increment_owned, increment);
  }



  template <int dim>
  const LA::MPI::Vector &
  DisplacementProblem<dim>::assemble_contact_residual()
  {
    // r = b - A(du) on the cells with a contact node, whose tangential part
    // at a contact node is its friction multiplier.
    contact_residual = 0.;
    assemble_residual(friction_problem->residual_cells(), contact_residual);
    contact_residual.compress(VectorOperation::add);
    return contact_residual;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::note_refactorization(const double time)
  {
    // A factorization anew for the changed stick set: the automatic choice
    // counts it, and may take CG with AMG from here on (LinearSolver::
    // switch_after_refactorization()); the screen says so.
    const auto step = static_cast<unsigned int>(
      std::lround(time / time_discretization.step_size()));
    if (displacement.solver.switch_after_refactorization(step))
      pcout << "  solver: " << displacement.solver.description()
            << ", from step " << step << " on" << std::endl;
  }



  template <int dim>
  bool
  DisplacementProblem<dim>::friction_sets_settled(const double       time,
                                                  const unsigned int iteration)
  {
    // The next contact, stick and slip sets from the multipliers of this
    // solve. The matrix changes when a node enters or leaves the contact or
    // the stick set (its constraints change) or, in 3D, when a slip
    // direction turns or a Coulomb bound moves (its slip stiffness
    // changes); then it is reassembled.
    const auto changes = friction_problem->update(increment,
                                                  solution,
                                                  material.youngs_modulus(),
                                                  assemble_contact_residual());
    if (changes.n_stick_changed > 0)
      check_held_while_slipping(time);
    if (changes.n_changed == 0)
      return true;
    check_sets_settle(time, iteration, changes);
    if (changes.n_stick_changed > 0)
      {
        make_constraints(time, &solution);
        assemble_stiffness_matrix();
        // A node that enters or leaves the stick set changes the rows and
        // columns of its tangential unknowns (with unilateral contact, of
        // all its unknowns). Where few change, CG preconditioned by the
        // factors or the AMG of the matrix as it was solves within a few
        // iterations, for less than new ones cost; LinearSolver rebuilds
        // them once the changes add up.
        const unsigned int rows
          = changes.n_stick_changed * (friction.unilateral() ? dim : dim - 1);
        if (displacement.solver.keeps_through(rows))
          displacement.solver.rows_changed(rows);
        else
          {
            note_refactorization(time);
            initialize_linear_solver();
          }
      }
    else if (changes.n_matrix_changed > 0)
      {
        // Only slip directions turned: the matrix changes at those nodes,
        // and the preconditioner or factors of the matrix as it was still
        // precondition CG well (LinearSolver::matrix_changed()). A
        // factorization begun in the background reads the matrix.
        displacement.solver.wait_for_factors();
        friction_problem->update_slip_stiffness(constraints,
                                                displacement.matrix);
        displacement.solver.matrix_changed();
      }
    return false;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::check_sets_settle(
    const double                                    time,
    const unsigned int                              iteration,
    const typename FrictionActiveSet<dim>::Changes &changes) const
  {
    // Stop an active-set iteration that cycles or runs out of iterations,
    // naming the entries that control it.
    AssertThrow(
      changes.cycle_length == 0,
      ExcMessage(
        "The contact active set cycles at t = " + to_text(time) + ": after "
        + std::to_string(iteration)
        + " iterations the contact, stick and slip sets are those of "
        + std::to_string(changes.cycle_length)
        + " iteration(s) before, so the semismooth Newton iteration will not "
          "settle. Try another Contact/Complementarity factor (now "
        + to_text(friction.complementarity_factor())
        + "), a smaller Time/Time step, or a finer mesh at the boundary "
          "of the contact zone. The output up to the previous step is "
          "complete in "
        + output_writer.directory() + "."));
    AssertThrow(
      iteration < friction.max_iterations(),
      ExcMessage(
        "The stick/slip active set did not converge at t = " + to_text(time)
        + ": after " + std::to_string(iteration) + " iterations "
        + std::to_string(changes.n_changed)
        + " contact node(s) still change set or slip direction. Raise Contact/Maximum active "
          "set iterations = "
        + std::to_string(friction.max_iterations())
        + ", try another Contact/Complementarity factor, or (3D) raise "
          "Contact/Slip direction tolerance = "
        + to_text(friction.direction_tolerance())
        + " if a displacement solver's tolerance keeps the directions "
          "from settling. The output up "
          "to the previous step is complete in "
        + output_writer.directory() + "."));
  }



  template <int dim>
  void
  DisplacementProblem<dim>::report_solve_floor()
  {
    // The floor of a time step: one solve of the displacement system with
    // everything reused (matrix and preconditioner as they are, the last
    // right-hand side), from a zero start vector.
    LA::MPI::Vector x(increment_owned.block(0));
    x = 0.;
    Timer              timer;
    const unsigned int iterations
      = displacement.solver.solve(x, displacement.rhs);
    timer.stop();

    // Its two kernels, each timed over ten applications: they tell how the
    // solve scales with the ranks (scripts/bench compares them).
    LA::MPI::Vector y(x);
    Timer           matvec_timer;
    for (unsigned int i = 0; i < 10; ++i)
      displacement.matrix.vmult(y, x);
    matvec_timer.stop();
    Timer preconditioner_timer;
    for (unsigned int i = 0; i < 10; ++i)
      displacement.solver.precondition(y, displacement.rhs);
    preconditioner_timer.stop();
    const bool        cg = !displacement.solver.is_direct();
    const std::string how
      = (cg ? std::to_string(iterations) + " CG iterations" :
              std::string("solve with the factors"));
    pcout << "Solve floor: one displacement solve takes " << timer.wall_time()
          << " s (" << how << ", " << displacement.matrix.m()
          << " dofs); one matrix-vector product "
          << 100. * matvec_timer.wall_time() << " ms, "
          << (cg ? "one preconditioner application " :
                   "one solve with the factors ")
          << 100. * preconditioner_timer.wall_time() << " ms" << std::endl;
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
