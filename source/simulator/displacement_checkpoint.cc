// The displacement problem's part of a checkpoint: u_n, du_n and the
// predictor's earlier increments as vectors on all degrees of freedom (the
// files' layout), and the state a resumed step needs.
#include <vpcontact/simulator/displacement_problem.h>

namespace VPContact
{
  template <int dim>
  std::array<LA::MPI::Vector, 3>
  DisplacementProblem<dim>::increments_for_checkpoint()
  {
    // du_n, du_{n-1} and du_{n-2} on all degrees of freedom, ghosted (the
    // predictor keeps the displacement block; the damage block is zero).
    std::array<LA::MPI::Vector, 3> increments;
    LA::MPI::BlockVector           recorded(increment_owned);
    for (unsigned int i = 0; i < increments.size(); ++i)
      {
        increments[i].reinit(locally_owned_dofs,
                             locally_relevant_dofs,
                             mpi_communicator);
        if (i > 0)
          {
            recorded = 0.;
            copy_owned_values(increment_predictor.recorded(i),
                              recorded.block(0));
          }
        ghosts.copy(i == 0 ? increment_owned : recorded, increments[i]);
      }
    return increments;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::restore_fields(
    const std::array<LA::MPI::Vector, 4> &full)
  {
    // u_n, du_n, du_{n-1}, du_{n-2}, owned, on all degrees of freedom.
    copy_into_blocks(full[0], solution_owned);
    copy_into_blocks(full[1], increment_owned);
    LA::MPI::BlockVector recorded(increment_owned);
    for (unsigned int i = 1; i < 3; ++i)
      {
        copy_into_blocks(full[i + 1], recorded);
        copy_owned_values(recorded.block(0), increment_predictor.recorded(i));
      }
    ghosts.copy(solution_owned, solution);
    ghosts.copy(increment_owned, increment);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::resume_at(const double       time,
                                      const unsigned int n_recorded)
  {
    // The constraints of the step read (with the stick set the friction
    // problem read), and the predictor's history as it was.
    make_constraints(time, &solution);
    copy_owned_values(increment_owned.block(0),
                      increment_predictor.recorded(0));
    increment_predictor.set_n_recorded(n_recorded);
  }



  template <int dim>
  std::map<std::string, double>
  DisplacementProblem<dim>::checkpoint_counters() const
  {
    // The predictor's count of increments, and the automatic solver
    // choice's state.
    const auto [n_refactorizations, switched]
      = displacement.solver.choice_state();
    return {{"recorded_increments", increment_predictor.n_recorded()},
            {"solver_refactorizations", n_refactorizations},
            {"solver_switched_to_amg", switched ? 1. : 0.}};
  }



  template <int dim>
  void
  DisplacementProblem<dim>::restore_solver_choice(
    const std::map<std::string, double> &counters)
  {
    // A checkpoint of a run that switched to AMG resumes with AMG, and
    // counts on from its factorizations anew; a checkpoint written before
    // these counters existed holds none, as a run that never switched.
    const auto counter = [&counters](const std::string &name) {
      const auto found = counters.find(name);
      return found == counters.end() ? 0. : found->second;
    };
    displacement.solver.restore_choice_state(
      static_cast<unsigned int>(counter("solver_refactorizations")),
      counter("solver_switched_to_amg") > 0);
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
