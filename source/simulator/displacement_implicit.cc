// The simulator's implicit (backward Euler) viscoplastic step: a global
// Newton iteration whose stress comes from a local Newton solve at every
// quadrature point, for laws too fast for the paper's explicit step.
#include <vpcontact/app/exit_agreement.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/simulator/displacement_problem.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace VPContact
{
  namespace
  {
    // What one quadrature point adds to the Newton system of a cell: the
    // tangent C in (C eps(phi_i), eps(phi_j)) JxW and the stress in
    // -(sigma(du), eps(phi_i)) JxW, on the displacement shape functions
    // @p shape. The symmetric gradients of the shape functions are computed
    // once into @p eps_phi, since every row and column uses them.
    template <int dim>
    void
    add_implicit_point_terms(const FEValuesViews::Vector<dim>     &fe_u,
                             const std::vector<unsigned int>      &shape,
                             const unsigned int                    q,
                             const double                          JxW,
                             const ImplicitStress<dim>            &update,
                             std::vector<SymmetricTensor<2, dim>> &eps_phi,
                             FullMatrix<double>                   &cell_matrix,
                             Vector<double>                       &cell_rhs)
    {
      const unsigned int dofs_per_cell = shape.size();
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        eps_phi[i] = fe_u.symmetric_gradient(shape[i], q);
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        {
          const SymmetricTensor<2, dim> C_eps_i = update.tangent * eps_phi[i];
          for (unsigned int j = 0; j < dofs_per_cell; ++j)
            cell_matrix(i, j) += (C_eps_i * eps_phi[j]) * JxW;
          cell_rhs(i) -= (update.stress * eps_phi[i]) * JxW;
        }
    }
  } // namespace



  // The cell matrix and right-hand side of the implicit step, and the
  // values they are computed from, for one pass over the cells: allocated
  // once, overwritten on every cell.
  template <int dim>
  struct DisplacementProblem<dim>::ImplicitCellData
  {
    ImplicitCellData(const unsigned int dofs_per_cell,
                     const unsigned int n_fe_dofs,
                     const unsigned int n_q_points)
      : cell_matrix(dofs_per_cell, dofs_per_cell)
      , cell_rhs(dofs_per_cell)
      , cell_loads(n_fe_dofs)
      , dof_indices(dofs_per_cell)
      , strains(n_q_points)
      , strain_increments(n_q_points)
      , eps_phi(dofs_per_cell)
      , damage_values(n_q_points, 1.)
    {}
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    Vector<double>                       cell_loads;
    std::vector<types::global_dof_index> dof_indices;
    std::vector<SymmetricTensor<2, dim>> strains;
    std::vector<SymmetricTensor<2, dim>> strain_increments;
    std::vector<SymmetricTensor<2, dim>> eps_phi;
    std::vector<double>                  damage_values;
  };



  template <int dim>
  void
  DisplacementProblem<dim>::assemble_implicit_system(const double time)
  {
    TimerOutput::Scope t(computing_timer, "Assemble implicit system");
    // The first step's assembly may come while the factorization of the
    // elastic matrix, begun in the background at set-up, still reads the
    // matrix that is about to be zeroed here: wait for it.
    displacement.solver.wait_for_factors();

    // At the current increment du: sigma(du) solves sigma - k G(sigma) =
    // sigma_{n-1} + E eps(du) at each quadrature point, with the tangent
    // C = (I - k dG/dsigma)^{-1} E. The Newton system is
    //   (C eps(delta), eps(v)) = (f_n, v) - (sigma(du), eps(v)).
    boundary_conditions.set_time(time);
    const double     k = time_discretization.step_size();
    AssemblyScratch  scratch(mapping,
                            fe,
                            quadrature,
                            discretization.face_quadrature());
    ImplicitCellData data(displacement.shape_functions.size(),
                          fe.n_dofs_per_cell(),
                          quadrature.size());

    displacement.matrix = 0.;
    displacement.rhs    = 0.;
    // The local Newton solve may fail at a point of one rank's cells only:
    // all ranks stop together, before the collective compress().
    stop_together(mpi_communicator, [&]() {
      for (const auto &cell : owned_cells)
        {
          assemble_implicit_cell(cell, k, scratch, data);
          get_displacement_dof_indices(cell, data.dof_indices);
          constraints.distribute_local_to_global(data.cell_matrix,
                                                 data.cell_rhs,
                                                 data.dof_indices,
                                                 displacement.matrix,
                                                 displacement.rhs);
        }
    });
    displacement.matrix.compress(VectorOperation::add);
    displacement.rhs.compress(VectorOperation::add);
  }



  // The Newton system on one cell, in @p data: the stress sigma(du) and
  // its tangent from the local Newton solve at every quadrature point
  // (implicit_stress_update()), and the loads f_n, restricted to the
  // displacement shape functions. The law sees the damage of the solution
  // in damage scenes, and 1 (undamaged) elsewhere.
  template <int dim>
  void
  DisplacementProblem<dim>::assemble_implicit_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const double                                          k,
    AssemblyScratch                                      &scratch,
    ImplicitCellData                                     &data)
  {
    FEValues<dim>                   &fe_values = scratch.fe_values;
    const FEValuesExtractors::Vector u(0);
    const FEValuesExtractors::Scalar zeta(dim);
    const std::vector<unsigned int> &shape = displacement.shape_functions;

    data.cell_matrix = 0.;
    data.cell_rhs    = 0.;
    data.cell_loads  = 0.;
    fe_values.reinit(cell);
    fe_values[u].get_function_symmetric_gradients(solution, data.strains);
    fe_values[u].get_function_symmetric_gradients(increment,
                                                  data.strain_increments);
    if (damage_model.is_active())
      fe_values[zeta].get_function_values(solution, data.damage_values);
    const auto history = stress_history.get_data(cell);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const auto update = implicit_stress_update(
          *viscoplastic_law,
          history[q].stress + material.stress(data.strain_increments[q]),
          data.strains[q] + data.strain_increments[q],
          data.damage_values[q],
          k,
          material.stiffness());
        add_implicit_point_terms(fe_values[u],
                                 shape,
                                 q,
                                 fe_values.JxW(q),
                                 update,
                                 data.eps_phi,
                                 data.cell_matrix,
                                 data.cell_rhs);
      }
    add_cell_loads(cell, fe_values, scratch.fe_face_values, data.cell_loads);
    for (unsigned int i = 0; i < shape.size(); ++i)
      data.cell_rhs(i) += data.cell_loads(shape[i]);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::solve_increment_implicit(const double time)
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
    ghosts.copy(increment_owned, increment);
    last_linear_iterations = 0;
    double first_residual  = 0;
    double last_update     = 0;
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
        last_update = apply_newton_correction(time, iteration);
        if (residual_norm == 0.)
          break;
      }
    solution_owned += increment_owned;
    ghosts.copy(solution_owned, solution);
  }



  // One Newton correction of the implicit step: solve the system that
  // assemble_implicit_system() left in displacement, add the correction to
  // du with its constraints, and return its norm for the convergence test.
  // The first correction brings du to the prescribed increments; the
  // constraints are then rebuilt with the increment g(t_n) - (u_{n-1} + du),
  // zero, so that the later corrections leave the prescribed boundary as it
  // is.
  template <int dim>
  double
  DisplacementProblem<dim>::apply_newton_correction(
    const double       time,
    const unsigned int iteration)
  {
    initialize_linear_solver();
    // The correction on the displacement block, with its constraints.
    LA::MPI::Vector update(displacement.owned, mpi_communicator);
    {
      TimerOutput::Scope t(computing_timer, "Solve");
      last_linear_iterations
        += displacement.solver.solve(update, displacement.rhs);
    }
    constraints.distribute(update);
    const double update_norm = update.l2_norm();
    increment_owned.block(0) += update;
    ghosts.copy(increment_owned, increment);
    if (iteration == 1 && boundary_conditions.has_prescribed_displacement())
      {
        LA::MPI::BlockVector total(solution_owned);
        total += increment_owned;
        LA::MPI::Vector total_relevant(solution);
        ghosts.copy(total, total_relevant);
        make_constraints(time, &total_relevant);
      }
    return update_norm;
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
