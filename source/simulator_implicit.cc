// The simulator's implicit (backward Euler) viscoplastic step: a global
// Newton iteration whose stress comes from a local Newton solve at every
// quadrature point, for laws too fast for the paper's explicit step.
#include <vpcontact/input_error.h>
#include <vpcontact/simulator.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::assemble_implicit_system(const double time)
  {
    TimerOutput::Scope t(computing_timer, "Assemble implicit system");

    // At the current increment du: sigma(du) solves sigma - k G(sigma) =
    // sigma_{n-1} + E eps(du) at each quadrature point, with the tangent
    // C = (I - k dG/dsigma)^{-1} E. The Newton system is
    //   (C eps(delta), eps(v)) = (f_n, v) - (sigma(du), eps(v)).
    boundary_conditions.set_time(time);
    const double                     k = time_discretization.step_size();
    AssemblyScratch                  scratch(fe, quadrature);
    FEValues<dim>                   &fe_values      = scratch.fe_values;
    FEFaceValues<dim>               &fe_face_values = scratch.fe_face_values;
    const FEValuesExtractors::Vector u(0);
    const FEValuesExtractors::Scalar zeta(dim);
    const std::vector<unsigned int> &shape = displacement.shape_functions;
    const unsigned int               dofs_per_cell = shape.size();
    FullMatrix<double>               cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>                   cell_rhs(dofs_per_cell);
    Vector<double>                   cell_loads(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> strain_increments(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> eps_phi(dofs_per_cell);
    std::vector<double>                  damage_values(quadrature.size(), 1.);

    displacement.matrix = 0.;
    displacement.rhs    = 0.;
    for (const auto &cell : owned_cells)
      {
        cell_matrix = 0.;
        cell_rhs    = 0.;
        cell_loads  = 0.;
        fe_values.reinit(cell);
        fe_values[u].get_function_symmetric_gradients(solution, strains);
        fe_values[u].get_function_symmetric_gradients(increment,
                                                      strain_increments);
        if (damage_model.is_active())
          fe_values[zeta].get_function_values(solution, damage_values);
        const auto history = stress_history.get_data(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const auto update = implicit_stress_update(
              *viscoplastic_law,
              history[q].stress + material.stress(strain_increments[q]),
              strains[q] + strain_increments[q],
              damage_values[q],
              k,
              material.stiffness());
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              eps_phi[i] = fe_values[u].symmetric_gradient(shape[i], q);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const SymmetricTensor<2, dim> C_eps_i
                  = update.tangent * eps_phi[i];
                for (unsigned int j = 0; j < dofs_per_cell; ++j)
                  cell_matrix(i, j)
                    += (C_eps_i * eps_phi[j]) * fe_values.JxW(q);
                cell_rhs(i) -= (update.stress * eps_phi[i]) * fe_values.JxW(q);
              }
          }
        add_cell_loads(cell, fe_values, fe_face_values, cell_loads);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          cell_rhs(i) += cell_loads(shape[i]);
        get_displacement_dof_indices(cell, dof_indices);
        constraints.distribute_local_to_global(cell_matrix,
                                               cell_rhs,
                                               dof_indices,
                                               displacement.matrix,
                                               displacement.rhs);
      }
    displacement.matrix.compress(VectorOperation::add);
    displacement.rhs.compress(VectorOperation::add);
  }



  template <int dim>
  void
  Simulator<dim>::solve_increment_implicit(const double time)
  {
    // The damage source phi_{n-1} is stored at the quadrature points by the
    // explicit assembly (its right-hand side is not used here).
    assemble_rhs(time, false);

    // Newton's method for du, from du = 0. The first correction carries the
    // prescribed increments (inhomogeneous constraints); after it the
    // constraints are homogeneous. The residual is the condensed one.
    constexpr double       newton_tolerance      = 1e-10;
    constexpr unsigned int max_newton_iterations = 50;
    increment_owned                              = 0.;
    increment                                    = increment_owned;
    last_linear_iterations                       = 0;
    double first_residual                        = 0;
    double last_update                           = 0;
    for (unsigned int iteration = 1;; ++iteration)
      {
        assemble_implicit_system(time);
        const double residual_norm = displacement.rhs.l2_norm();
        AssertThrow(std::isfinite(residual_norm),
                    ExcMessage("The implicit step at t = " + to_text(time)
                               + " produced a residual that is not finite. The "
                                 "output up to the previous step is complete "
                                 "in "
                               + output_writer.directory() + "."));
        // Converged when the residual has dropped by the tolerance, or when
        // the last correction is round-off against the displacement (a
        // step that starts in equilibrium has nothing to reduce).
        if (iteration == 1)
          first_residual = residual_norm;
        else if (residual_norm <= newton_tolerance * first_residual
                 || last_update <= 1e-12
                                     * (solution_owned.l2_norm()
                                        + increment_owned.l2_norm()))
          break;
        AssertThrow(iteration < max_newton_iterations,
                    ExcMessage("The Newton iteration of the implicit "
                               "viscoplastic step did not converge at t = "
                               + to_text(time) + ": residual "
                               + to_text(residual_norm) + " after "
                               + std::to_string(iteration)
                               + " iterations. Reduce Time/Time step."));
        initialize_linear_solver();
        newton_update = 0.;
        {
          TimerOutput::Scope t(computing_timer, "Solve");
          last_linear_iterations
            += displacement.solver.solve(newton_update, displacement.rhs);
        }
        // The update on all degrees of freedom (the displacement ones lead
        // the local entries), with its constraints.
        TrilinosWrappers::MPI::Vector update(increment_owned);
        update = 0.;
        std::copy(newton_update.begin(), newton_update.end(), update.begin());
        constraints.distribute(update);
        last_update = update.l2_norm();
        increment_owned += update;
        increment = increment_owned;
        if (iteration == 1 && boundary_conditions.has_prescribed_displacement())
          {
            TrilinosWrappers::MPI::Vector total(solution_owned);
            total += increment_owned;
            TrilinosWrappers::MPI::Vector total_relevant(solution);
            total_relevant = total;
            make_constraints(time, &total_relevant);
          }
        if (residual_norm == 0.)
          break;
      }
    solution_owned += increment_owned;
    solution = solution_owned;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
