// The simulator's damage field: its degrees of freedom, the obstacle problem
// of step 4 of the scheme with its bounds, and the damage statistics.
#include <vpcontact/input_error.h>
#include <vpcontact/simulator.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <functional>
#include <limits>

namespace VPContact
{
  namespace
  {
    // The element matrix M_L/k + kappa A and vector M_L zeta_{n-1}/k +
    // (phi_{n-1}, psi) of the damage problem on one cell: the mass with the
    // Gauss-Lobatto rule (lumped), the rest with the Gauss rule of the
    // stored source. Rows of displacement shape functions stay zero.
    template <int dim>
    void
    damage_cell_system(
      const FEValues<dim>       &fe_values,
      const FEValues<dim>       &lobatto_values,
      const std::vector<double> &old_damage,
      const std::vector<std::shared_ptr<QuadraturePointHistory<dim>>> &history,
      const double                                                     k,
      const double                                                     kappa,
      FullMatrix<double> &cell_matrix,
      Vector<double>     &cell_rhs)
    {
      const FEValuesExtractors::Scalar zeta(dim);
      const FiniteElement<dim>        &fe = fe_values.get_fe();
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        if (fe.system_to_component_index(i).first == dim)
          {
            for (const unsigned int q :
                 lobatto_values.quadrature_point_indices())
              {
                const double psi_i = lobatto_values[zeta].value(i, q);
                cell_rhs(i)
                  += psi_i * old_damage[q] / k * lobatto_values.JxW(q);
                for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
                  cell_matrix(i, j) += psi_i * lobatto_values[zeta].value(j, q)
                                       / k * lobatto_values.JxW(q);
              }
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                cell_rhs(i) += history[q]->damage_source
                               * fe_values[zeta].value(i, q) * fe_values.JxW(q);
                for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
                  cell_matrix(i, j) += kappa * fe_values[zeta].gradient(i, q)
                                       * fe_values[zeta].gradient(j, q)
                                       * fe_values.JxW(q);
              }
          }
    }
  } // namespace



  template <int dim>
  IndexSet
  Simulator<dim>::relevant_dofs_of_components(const unsigned int first,
                                              const unsigned int last) const
  {
    // The degrees of freedom of components [first, last) on every cell this
    // rank sees, i.e. the locally relevant ones of those components.
    IndexSet                             dofs(dof_handler.n_dofs());
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c >= first && c < last)
                dofs.add_index(dof_indices[i]);
            }
        }
    dofs.compress();
    return dofs;
  }



  template <int dim>
  void
  Simulator<dim>::setup_damage()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    // As in setup_dofs(): the bound sets of an earlier mesh must not enter
    // the constraints built here before setup_mass_and_bounds().
    damage_bounds = DamageBounds();
    damage_dofs   = relevant_dofs_of_components(dim, dim + 1);

    // The sparsity pattern of M/k + kappa A without the bounds: every
    // displacement dof is constrained, so its rows hold only the diagonal.
    // Bound constraints later remove entries, never add them.
    make_damage_constraints();
    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    damage_constraints,
                                    false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    damage_amg.clear(); // it refers to the matrix of the last mesh
    damage_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    damage_rhs.reinit(locally_owned_dofs, mpi_communicator);
    damage_owned.reinit(locally_owned_dofs, mpi_communicator);
    damage_change.reinit(locally_owned_dofs, mpi_communicator);
    damage.reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
    damage_load_assembly.reinit(locally_owned_dofs,
                                locally_relevant_dofs,
                                mpi_communicator,
                                true);
    damage_load.reinit(locally_owned_dofs, mpi_communicator);
    damage_residual_owned.reinit(locally_owned_dofs, mpi_communicator);
    damage_residual.reinit(locally_owned_dofs,
                           locally_relevant_dofs,
                           mpi_communicator);

    setup_mass_and_bounds();
    interpolate_initial_damage();

    // K = M_L/k + kappa A does not change while the mesh and k do: it is
    // assembled and its AMG built once. The bounds are applied by masking
    // (see solve_damage()), not by reassembly.
    assemble_damage(true);
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic       = true;
    data.constant_modes = all_constant_modes;
    damage_amg.initialize(damage_matrix, data);
  }



  template <int dim>
  void
  Simulator<dim>::setup_mass_and_bounds()
  {
    // The lumped mass m_i = int psi_i: the mass matrix integrated with the
    // Gauss-Lobatto (trapezoidal) rule, which is diagonal for Q1. On
    // adaptive meshes it is condensed like the load: a hanging node hands
    // its mass to the nodes it depends on, and carries no bound itself (its
    // value is an average of theirs, within [0, 1] when theirs are).
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();
    const QGaussLobatto<dim> lobatto(2);
    FEValues<dim> fe_values(fe, lobatto, update_values | update_JxW_values);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    Vector<double>                       cell_mass(fe.n_dofs_per_cell());
    TrilinosWrappers::MPI::Vector        mass;
    mass.reinit(locally_owned_dofs,
                locally_relevant_dofs,
                mpi_communicator,
                true);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dof_indices);
          cell_mass = 0.;
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (fe.system_to_component_index(i).first == dim)
              for (const unsigned int q : fe_values.quadrature_point_indices())
                cell_mass(i) += fe_values.shape_value(i, q) * fe_values.JxW(q);
          hanging_node_constraints.distribute_local_to_global(cell_mass,
                                                              dof_indices,
                                                              mass);
        }
    mass.compress(VectorOperation::add);
    lumped_mass.reinit(locally_owned_dofs,
                       locally_relevant_dofs,
                       mpi_communicator);
    lumped_mass = mass;
    IndexSet bounded_dofs(dof_handler.n_dofs());
    for (const auto dof : damage_dofs)
      if (!hanging_node_constraints.is_constrained(dof))
        bounded_dofs.add_index(dof);
    bounded_dofs.compress();
    damage_bounds.setup(bounded_dofs,
                        locally_owned_dofs,
                        lumped_mass,
                        mpi_communicator);
  }



  template <int dim>
  void
  Simulator<dim>::interpolate_initial_damage()
  {
    // zeta_0, checked against the bounds at every node.
    VectorFunctionFromScalarFunctionObject<dim> initial(
      [&](const Point<dim> &p) {
        return damage_model.initial_damage().value(p);
      },
      dim,
      fe.n_components());
    ComponentMask damage_mask(fe.n_components(), false);
    damage_mask.set(dim, true);
    VectorTools::interpolate(dof_handler, initial, damage_owned, damage_mask);
    hanging_node_constraints.distribute(damage_owned);
    const auto [lowest, highest] = damage_range(damage_owned);
    VPContactCheckParameter(lowest >= 0 && highest <= 1,
                            "Damage/Initial damage",
                            "[" + to_text(lowest) + ", " + to_text(highest)
                              + "] (range at the nodes)",
                            "the damage must lie in [0, 1] (1 is sound).");
    solution_owned += damage_owned;
    solution = solution_owned;
  }



  template <int dim>
  std::pair<double, double>
  Simulator<dim>::damage_range(const TrilinosWrappers::MPI::Vector &v) const
  {
    // min and max of the damage entries of v, over all ranks.
    double lowest  = std::numeric_limits<double>::max();
    double highest = -std::numeric_limits<double>::max();
    for (const auto dof : damage_dofs)
      if (locally_owned_dofs.is_element(dof))
        {
          const double value = v(dof);
          lowest             = std::min(lowest, value);
          highest            = std::max(highest, value);
        }
    return {Utilities::MPI::min(lowest, mpi_communicator),
            Utilities::MPI::max(highest, mpi_communicator)};
  }



  template <int dim>
  void
  Simulator<dim>::make_damage_constraints()
  {
    // Only the damage is unknown here: every displacement dof is held (at
    // zero in this auxiliary vector), hanging nodes as usual, and the nodes
    // of the active sets at their bound.
    damage_constraints.clear();
    damage_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, damage_constraints);
    for (const auto dof : relevant_dofs_of_components(0, dim))
      if (!damage_constraints.is_constrained(dof))
        damage_constraints.add_line(dof);
    damage_bounds.add_constraints(damage_constraints, solution);
    damage_constraints.close();
  }



  template <int dim>
  void
  Simulator<dim>::assemble_damage(const bool matrix)
  {
    TimerOutput::Scope t(computing_timer, "Damage assembly");

    // K = M_L/k + kappa A (with matrix) or b = M_L zeta_{n-1}/k +
    // (phi_{n-1}, psi) (without): the lumped mass M_L (Gauss-Lobatto
    // points, where psi_i psi_j vanishes for i != j), and the source stored
    // at the Gauss points by assemble_rhs(). The matrix holds every
    // displacement dof (the constraints without bounds); b is condensed on
    // hanging nodes only, so that it carries no bound.
    const double                     k     = time_discretization.step_size();
    const double                     kappa = damage_model.diffusion();
    const QGaussLobatto<dim>         lobatto(2);
    FEValues<dim>                    fe_values(fe,
                            quadrature,
                            update_values | update_gradients
                              | update_JxW_values);
    FEValues<dim>                    lobatto_values(fe,
                                 lobatto,
                                 update_values | update_JxW_values);
    const FEValuesExtractors::Scalar zeta(dim);
    const unsigned int               dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double>               cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double>                   cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::vector<double>                  old_damage(lobatto.size(), 1.);

    if (matrix)
      damage_matrix = 0.;
    else
      damage_load_assembly = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix = 0.;
          cell_rhs    = 0.;
          fe_values.reinit(cell);
          lobatto_values.reinit(cell);
          if (!matrix)
            lobatto_values[zeta].get_function_values(solution, old_damage);
          damage_cell_system(fe_values,
                             lobatto_values,
                             old_damage,
                             stress_history.get_data(cell),
                             k,
                             kappa,
                             cell_matrix,
                             cell_rhs);
          cell->get_dof_indices(dof_indices);
          if (matrix)
            damage_constraints.distribute_local_to_global(cell_matrix,
                                                          dof_indices,
                                                          damage_matrix);
          else
            hanging_node_constraints.distribute_local_to_global(
              cell_rhs,
              dof_indices,
              damage_load_assembly);
        }
    if (matrix)
      damage_matrix.compress(VectorOperation::add);
    else
      {
        damage_load_assembly.compress(VectorOperation::add);
        damage_load = damage_load_assembly;
      }
  }



  template <int dim>
  void
  Simulator<dim>::solve_masked_damage_system(
    const std::vector<types::global_dof_index> &held)
  {
    TimerOutput::Scope t(computing_timer, "Damage solve");

    // CG on x -> P K P x + (I - P) x, with P zeroing the held entries: the
    // system of the free nodes, with the identity on the held ones, so that
    // neither K nor its AMG has to be rebuilt when the sets change. The
    // preconditioner is masked alike: P AMG(K) P + (I - P).
    struct Masked
    {
      std::function<void(TrilinosWrappers::MPI::Vector &,
                         const TrilinosWrappers::MPI::Vector &)>
                                                  apply;
      const std::vector<types::global_dof_index> &held;
      mutable TrilinosWrappers::MPI::Vector       tmp;
      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        tmp = src;
        for (const auto dof : held)
          tmp(dof) = 0.;
        tmp.compress(VectorOperation::insert);
        apply(dst, tmp);
        for (const auto dof : held)
          dst(dof) = src(dof);
        dst.compress(VectorOperation::insert);
      }
    };
    const Masked operator_on_free{[this](auto &dst, const auto &src) {
                                    damage_matrix.vmult(dst, src);
                                  },
                                  held,
                                  damage_rhs};
    const Masked preconditioner_on_free{[this](auto &dst, const auto &src) {
                                          damage_amg.vmult(dst, src);
                                        },
                                        held,
                                        damage_rhs};

    const double rhs_norm = damage_rhs.l2_norm();
    if (rhs_norm == 0.)
      {
        damage_change = 0.;
        return;
      }
    SolverControl control(linear_solver.iteration_limit(),
                          linear_solver.tolerance() * rhs_norm);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(operator_on_free,
                 damage_change,
                 damage_rhs,
                 preconditioner_on_free);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        AssertThrow(false,
                    ExcMessage("CG did not converge for the damage: after "
                               + std::to_string(e.last_step)
                               + " iterations the residual is "
                               + to_text(e.last_residual) + " > "
                               + to_text(control.tolerance())
                               + ". Raise Solver/Maximum linear iterations or "
                                 "loosen Solver/Relative tolerance."));
      }
  }



  template <int dim>
  void
  Simulator<dim>::solve_damage(const unsigned int n)
  {
    // The primal-dual active set for 0 <= zeta <= 1, warm-started from the
    // sets of the previous step: solve with the nodes of the active sets at
    // their bound, recompute the multipliers from the residual, take the
    // next sets, until no node changes. The unknown of the linear solves is
    // the change zeta - zeta_{n-1}: its right-hand side F - kappa A
    // zeta_{n-1} is small where little happens, so the relative tolerance
    // of CG measures what changes, not the mass term M zeta_{n-1}/k.
    last_damage_iterations = 0;
    damage_change          = 0.;

    // b and b - K zeta_{n-1} of this step, free of bounds (K is the same on
    // the damage rows with or without the held displacement dofs).
    assemble_damage(false);
    TrilinosWrappers::MPI::Vector old_owned(damage_owned),
      step_rhs(damage_owned), bound_change(damage_owned);
    old_owned = solution;
    damage_matrix.vmult(step_rhs, old_owned);
    step_rhs.sadd(-1., 1., damage_load);

    for (unsigned int iteration = 1;; ++iteration)
      {
        // The held nodes: every displacement dof, and the damage nodes at a
        // bound (their change is prescribed).
        make_damage_constraints();
        std::vector<types::global_dof_index> held;
        bound_change = 0.;
        for (const auto dof : locally_owned_dofs)
          if (damage_constraints.is_constrained(dof))
            {
              held.push_back(dof);
              bound_change(dof) = damage_constraints.get_inhomogeneity(dof);
            }
        bound_change.compress(VectorOperation::insert);

        // The free nodes solve K_FF change_F = (b - K (zeta_{n-1} +
        // bound_change))_F; the held rows of the right-hand side are zero.
        damage_matrix.vmult(damage_rhs, bound_change);
        damage_rhs.sadd(-1., 1., step_rhs);
        for (const auto dof : held)
          damage_rhs(dof) = 0.;
        damage_rhs.compress(VectorOperation::insert);
        solve_masked_damage_system(held);
        damage_constraints.distribute(damage_change);

        // zeta = zeta_{n-1} + change on the damage dofs (the displacement
        // entries of these vectors are not used).
        damage_owned = old_owned;
        damage_owned += damage_change;
        damage                 = damage_owned;
        last_damage_iterations = iteration;

        // The multipliers r = b - K zeta (bounds not condensed; hanging
        // nodes carry none).
        damage_matrix.vmult(damage_residual_owned, damage_owned);
        damage_residual_owned.sadd(-1., 1., damage_load);
        damage_residual = damage_residual_owned;
        const unsigned int n_changed
          = damage_bounds.update(damage_residual,
                                 damage,
                                 time_discretization.step_size());
        if (n_changed == 0)
          break;
        AssertThrow(iteration < damage_model.max_iterations(),
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
                        "the iteration need not be monotone. The output up to "
                        "step "
                      + std::to_string(n - 1) + " is complete in "
                      + output_writer.directory() + "."));
      }

    store_damage(n);
  }



  template <int dim>
  void
  Simulator<dim>::store_damage(const unsigned int n)
  {
    // Nodes between the bounds satisfy them up to the solver tolerance;
    // clip them onto [0, 1] (the exact discrete solution lies there) and
    // record by how much, then store zeta_n in the solution.
    double clip = 0;
    for (const auto dof : damage_dofs)
      if (locally_owned_dofs.is_element(dof))
        {
          const double value   = damage_owned(dof);
          const double clipped = std::clamp(value, 0., 1.);
          // NaN compares false: the clip becomes infinite and is caught
          // below, on every rank alike.
          clip
            = (std::abs(value - clipped) <= clip ? clip :
               std::isfinite(value)              ? std::abs(value - clipped) :
                                      std::numeric_limits<double>::infinity());
          damage_owned(dof)   = clipped;
          solution_owned(dof) = clipped;
        }
    clip = Utilities::MPI::max(clip, mpi_communicator);
    AssertThrow(std::isfinite(clip),
                ExcMessage("Step " + std::to_string(n)
                           + ": the damage is not finite. The output up to the "
                             "previous step is complete in "
                           + output_writer.directory() + "."));
    damage_owned.compress(VectorOperation::insert);
    solution_owned.compress(VectorOperation::insert);
    // Hanging nodes take the average of their (clipped) parents again.
    hanging_node_constraints.distribute(damage_owned);
    hanging_node_constraints.distribute(solution_owned);
    last_damage_clip = clip;
    damage           = damage_owned;
    solution         = solution_owned;
  }



  template <int dim>
  void
  Simulator<dim>::add_damage_statistics(std::string &line)
  {
    // Nodal extremes, the bound violation (which must be exactly 0), and the
    // volume fraction where zeta < 1 at the quadrature points.
    const auto [lowest, highest] = damage_range(solution);
    const double violation       = std::max({0., -lowest, highest - 1.});

    FEValues<dim> fe_values(fe, quadrature, update_values | update_JxW_values);
    const FEValuesExtractors::Scalar zeta(dim);
    std::vector<double>              values(quadrature.size());
    double                           damaged = 0, volume = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[zeta].get_function_values(solution, values);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              volume += fe_values.JxW(q);
              if (values[q] < 1. - 1e-12)
                damaged += fe_values.JxW(q);
            }
        }
    const double fraction = Utilities::MPI::sum(damaged, mpi_communicator)
                            / Utilities::MPI::sum(volume, mpi_communicator);
    max_damage_violation = std::max(max_damage_violation, violation);

    statistics.add_value("damage_min", lowest);
    statistics.add_value("damage_max", highest);
    statistics.add_value("damaged_fraction", fraction);
    statistics.add_value("damage_bound_violation", violation);
    statistics.add_value("damage_clip", last_damage_clip);
    statistics.add_value("damage_iterations", last_damage_iterations);
    line += "  zeta in [" + to_text(std::round(lowest * 1e6) / 1e6) + ", "
            + to_text(std::round(highest * 1e6) / 1e6) + "]  damaged "
            + to_text(std::round(fraction * 1e4) / 1e2) + "%";
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
