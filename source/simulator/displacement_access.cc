// What the displacement problem lets the simulator and the other physics
// objects read: its fields, stress history, laws and counters.
#include <vpcontact/simulator/displacement_problem.h>

namespace VPContact
{
  template <int dim>
  double
  DisplacementProblem<dim>::displacement_limit() const
  {
    return viscoplasticity.divergence_limit() * body_size;
  }



  template <int dim>
  bool
  DisplacementProblem<dim>::implicit() const
  {
    return viscoplasticity.implicit();
  }



  template <int dim>
  LA::MPI::BlockVector &
  DisplacementProblem<dim>::solution_blocks()
  {
    return solution_owned;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::update_ghosted_solution()
  {
    ghosts.copy(solution_owned, solution);
  }



  template <int dim>
  const LA::MPI::Vector &
  DisplacementProblem<dim>::ghosted_solution() const
  {
    return solution;
  }



  template <int dim>
  LA::MPI::BlockVector &
  DisplacementProblem<dim>::increment_blocks()
  {
    return increment_owned;
  }



  template <int dim>
  const LA::MPI::Vector &
  DisplacementProblem<dim>::ghosted_increment() const
  {
    return increment;
  }



  template <int dim>
  StressHistory<dim> &
  DisplacementProblem<dim>::history()
  {
    stress_sums_current = false;
    return stress_history;
  }



  template <int dim>
  const StressHistory<dim> &
  DisplacementProblem<dim>::history() const
  {
    return stress_history;
  }



  template <int dim>
  const CellKinematics<dim> &
  DisplacementProblem<dim>::kinematics() const
  {
    return cell_kinematics;
  }



  template <int dim>
  const std::vector<typename DisplacementProblem<dim>::cell_iterator> &
  DisplacementProblem<dim>::cells() const
  {
    return owned_cells;
  }



  template <int dim>
  const ElasticMaterial<dim> &
  DisplacementProblem<dim>::elastic_material() const
  {
    return material;
  }



  template <int dim>
  const ViscoplasticityParameters<dim> &
  DisplacementProblem<dim>::viscoplasticity_parameters() const
  {
    return viscoplasticity;
  }



  template <int dim>
  const ViscoplasticLaw<dim> &
  DisplacementProblem<dim>::law() const
  {
    return *viscoplastic_law;
  }



  template <int dim>
  const BoundaryConditions<dim> &
  DisplacementProblem<dim>::boundaries() const
  {
    return boundary_conditions;
  }



  template <int dim>
  std::string
  DisplacementProblem<dim>::contact_description() const
  {
    if (!boundary_conditions.has_contact_boundary())
      return "none";
    const std::string normal = friction.unilateral() ?
                                 "unilateral (u.nu <= g_0)" :
                                 "bilateral (u.nu = 0)";
    if (largest_friction == 0)
      return normal + ", frictionless (friction bound 0)"
             + (friction_problem ? ", primal-dual active set" : "");
    const bool coulomb
      = friction.friction_law() == TrescaFriction<dim>::FrictionLaw::coulomb;
    return normal + " with " + (coulomb ? "Coulomb" : "Tresca")
           + " friction, primal-dual active set";
  }



  template <int dim>
  const FrictionProblem<dim> *
  DisplacementProblem<dim>::contact() const
  {
    return friction_problem.get();
  }



  template <int dim>
  FrictionProblem<dim> *
  DisplacementProblem<dim>::contact()
  {
    return friction_problem.get();
  }



  template <int dim>
  IncrementPredictor &
  DisplacementProblem<dim>::predictor()
  {
    return increment_predictor;
  }



  template <int dim>
  const LinearSolver &
  DisplacementProblem<dim>::solver() const
  {
    return displacement.solver;
  }



  template <int dim>
  unsigned int
  DisplacementProblem<dim>::linear_iterations() const
  {
    return last_linear_iterations;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::reset_linear_iterations()
  {
    last_linear_iterations = 0;
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
