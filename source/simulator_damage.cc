// The simulator's damage field: its degrees of freedom, the lumped mass and
// the bounds' setup, the initial damage, and the assembly of the damage
// problem (its solve is in simulator_damage_solve.cc).
#include <vpcontact/finite_values.h>
#include <vpcontact/input_error.h>
#include <vpcontact/simulator.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace VPContact
{
  namespace
  {
    // The element matrix M_L/k + kappa A of the damage problem on one cell,
    // on its damage shape functions @p shape: the mass with the
    // Gauss-Lobatto rule (lumped), the diffusion with the Gauss rule.
    template <int dim>
    void
    damage_cell_matrix(const FEValues<dim>             &fe_values,
                       const FEValues<dim>             &lobatto_values,
                       const std::vector<unsigned int> &shape,
                       const double                     k,
                       const double                     kappa,
                       FullMatrix<double>              &cell_matrix)
    {
      for (unsigned int a = 0; a < shape.size(); ++a)
        for (unsigned int b = 0; b < shape.size(); ++b)
          {
            double entry = 0;
            for (const unsigned int q :
                 lobatto_values.quadrature_point_indices())
              entry += lobatto_values.shape_value(shape[a], q)
                       * lobatto_values.shape_value(shape[b], q) / k
                       * lobatto_values.JxW(q);
            for (const unsigned int q : fe_values.quadrature_point_indices())
              entry += kappa * fe_values.shape_grad(shape[a], q)
                       * fe_values.shape_grad(shape[b], q) * fe_values.JxW(q);
            cell_matrix(a, b) = entry;
          }
    }



    // The values psi(q, a) of the damage shape functions @p shape of @p fe
    // at the points of @p quadrature on the reference cell. They are those
    // of every cell (the values of a Q1 function do not depend on the
    // mapping), so the passes over the cells in every step need from
    // FEValues at most JxW, and those are stored once per mesh: no FEValues
    // copies the FESystem's shape functions on every cell.
    template <int dim>
    FullMatrix<double>
    reference_shape_values(const FiniteElement<dim>        &fe,
                           const std::vector<unsigned int> &shape,
                           const Quadrature<dim>           &quadrature)
    {
      FullMatrix<double> psi(quadrature.size(), shape.size());
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        for (unsigned int a = 0; a < shape.size(); ++a)
          psi(q, a) = fe.shape_value(shape[a], quadrature.point(q));
      return psi;
    }



    // The element load M_L zeta_{n-1}/k + (phi_{n-1}, psi) of one cell. The
    // lumped mass term is the cell's Gauss-Lobatto mass @p cell_mass of each
    // node times its zeta_{n-1} (@p old_nodal): at the Gauss-Lobatto points
    // psi_a(x_b) = delta_ab, so the rule collapses to one term per node. The
    // source is stored at the Gauss points by the assembly of the
    // displacement step, integrated with the shape values @p psi_gauss of
    // reference_shape_values() and the JxW stored with it.
    template <int dim>
    void
    damage_cell_load(
      const double                                       *cell_mass,
      const std::vector<double>                          &old_nodal,
      const FullMatrix<double>                           &psi_gauss,
      const ArrayView<const double>                      &JxW,
      const ArrayView<const QuadraturePointHistory<dim>> &history,
      const double                                        k,
      Vector<double>                                     &cell_rhs)
    {
      const unsigned int n_shape = old_nodal.size();
      for (unsigned int a = 0; a < n_shape; ++a)
        cell_rhs(a) = cell_mass[a] * old_nodal[a] / k;
      for (unsigned int q = 0; q < JxW.size(); ++q)
        {
          const double weight = history[q].damage_source * JxW[q];
          for (unsigned int a = 0; a < n_shape; ++a)
            cell_rhs(a) += psi_gauss(q, a) * weight;
        }
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::setup_damage()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    // As in setup_dofs(): the bound sets of an earlier mesh must not survive
    // into this one.
    damage_bounds      = DamageBounds();
    damage_rings_ahead = 0;
    damage_model.check_diffusion_length(GridTools::minimal_cell_diameter(
                                          triangulation),
                                        time_discretization.step_size());
    damage_system.reinit(dof_handler,
                         dim,
                         locally_owned_dofs,
                         locally_relevant_dofs,
                         mpi_communicator);
    const IndexSet &owned    = damage_system.owned();
    const IndexSet &relevant = damage_system.relevant();
    for (auto *v : {&damage_old,
                    &damage_owned,
                    &damage_change,
                    &damage_rhs,
                    &damage_load,
                    &damage_residual_owned,
                    &damage_bound_change})
      v->reinit(owned, mpi_communicator);
    damage.reinit(owned, relevant, mpi_communicator);
    damage_residual.reinit(owned, relevant, mpi_communicator);
    damage_load_assembly.reinit(owned, relevant, mpi_communicator, true);

    setup_mass_and_bounds();
    interpolate_initial_damage();

    // K = M_L/k + kappa A does not change while the mesh and k do: it is
    // assembled and its preconditioner built once. The bounds are applied by
    // masking (see DamageSystem::solve()), not by reassembly.
    assemble_damage(true);
    damage_system.initialize_preconditioner();
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
    const auto &constraints = damage_system.hanging_node_constraints();
    const auto &shape       = damage_system.shape_functions();
    const QGaussLobatto<dim> lobatto(2);
    FEValues<dim> fe_values(fe, lobatto, update_values | update_JxW_values);
    std::vector<types::global_dof_index> dof_indices;
    Vector<double>                       cell_mass(shape.size());
    TrilinosWrappers::MPI::Vector        mass;
    mass.reinit(damage_system.owned(),
                damage_system.relevant(),
                mpi_communicator,
                true);
    const unsigned int     n_shape     = shape.size();
    const Epetra_BlockMap &ghosted_map = damage.trilinos_vector().Map();
    damage_cell_mass.assign(triangulation.n_active_cells() * n_shape, 0.);
    damage_cell_positions.assign(triangulation.n_active_cells() * n_shape, 0);
    damage_cell_owned.assign(triangulation.n_active_cells() * n_shape, -1);
    const IndexSet &owned_damage = damage_system.owned();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          damage_system.dof_indices(cell, dof_indices);
          cell_mass = 0.;
          for (unsigned int a = 0; a < n_shape; ++a)
            for (const unsigned int q : fe_values.quadrature_point_indices())
              cell_mass(a)
                += fe_values.shape_value(shape[a], q) * fe_values.JxW(q);
          constraints.distribute_local_to_global(cell_mass, dof_indices, mass);
          const unsigned int first = cell->active_cell_index() * n_shape;
          for (unsigned int a = 0; a < n_shape; ++a)
            {
              damage_cell_mass[first + a]      = cell_mass(a);
              damage_cell_positions[first + a] = ghosted_map.LID(
                static_cast<TrilinosWrappers::types::int_type>(dof_indices[a]));
            }
          bool plain = true;
          for (unsigned int a = 0; a < n_shape; ++a)
            plain = plain && owned_damage.is_element(dof_indices[a])
                    && !constraints.is_constrained(dof_indices[a]);
          if (plain)
            for (unsigned int a = 0; a < n_shape; ++a)
              damage_cell_owned[first + a]
                = owned_damage.index_within_set(dof_indices[a]);
        }
    mass.compress(VectorOperation::add);
    lumped_mass.reinit(damage_system.owned(),
                       damage_system.relevant(),
                       mpi_communicator);
    lumped_mass = mass;
    IndexSet bounded_dofs(damage_system.relevant().size());
    for (const auto dof : damage_system.relevant())
      if (!constraints.is_constrained(dof))
        bounded_dofs.add_index(dof);
    bounded_dofs.compress();
    damage_bounds.setup(bounded_dofs,
                        damage_system.owned(),
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
    TrilinosWrappers::MPI::Vector interpolated(locally_owned_dofs,
                                               mpi_communicator);
    VectorTools::interpolate(dof_handler, initial, interpolated, damage_mask);
    damage_system.gather(interpolated, damage_owned);
    damage_system.distribute_hanging_nodes(damage_owned);
    // A NaN compares false with everything and would pass the range check
    // below unseen.
    damage_model.check_initial_damage_finite(
      all_finite(damage_owned, mpi_communicator));
    const auto [lowest, highest] = damage_range(damage_owned);
    VPContactCheckParameter(lowest >= 0 && highest <= 1,
                            "Damage/Initial damage",
                            "[" + to_text(lowest) + ", " + to_text(highest)
                              + "] (range at the nodes)",
                            "the damage must lie in [0, 1] (1 is sound).");
    damage_system.scatter(damage_owned, solution_owned);
    solution = solution_owned;
    damage   = damage_owned;
  }



  template <int dim>
  std::pair<double, double>
  Simulator<dim>::damage_range(const TrilinosWrappers::MPI::Vector &v) const
  {
    // min and max of the owned entries of a compact damage vector, over all
    // ranks.
    double lowest  = std::numeric_limits<double>::max();
    double highest = -std::numeric_limits<double>::max();
    for (const double value : v)
      {
        lowest  = std::min(lowest, value);
        highest = std::max(highest, value);
      }
    return {Utilities::MPI::min(lowest, mpi_communicator),
            Utilities::MPI::max(highest, mpi_communicator)};
  }



  template <int dim>
  void
  Simulator<dim>::assemble_damage(const bool matrix)
  {
    TimerOutput::Scope t(computing_timer, "Damage assembly");

    // K = M_L/k + kappa A (with matrix) or b = M_L zeta_{n-1}/k +
    // (phi_{n-1}, psi) (without): the lumped mass M_L (Gauss-Lobatto
    // points, where psi_i psi_j vanishes for i != j), and the source stored
    // at the Gauss points by assemble_rhs(), with zeta_{n-1} from the
    // ghosted compact vector damage. Both are condensed on hanging nodes
    // only: the bounds are imposed by the solver.
    const auto &shape       = damage_system.shape_functions();
    const auto &constraints = damage_system.hanging_node_constraints();
    std::vector<types::global_dof_index> dof_indices;
    if (matrix)
      {
        const double             k     = time_discretization.step_size();
        const double             kappa = damage_model.diffusion();
        const QGaussLobatto<dim> lobatto(2);
        FEValues<dim>            fe_values(fe,
                                quadrature,
                                update_gradients | update_JxW_values);
        FEValues<dim>            lobatto_values(fe,
                                     lobatto,
                                     update_values | update_JxW_values);
        FullMatrix<double>       cell_matrix(shape.size(), shape.size());
        damage_system.matrix() = 0.;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              lobatto_values.reinit(cell);
              damage_system.dof_indices(cell, dof_indices);
              damage_cell_matrix(fe_values,
                                 lobatto_values,
                                 shape,
                                 k,
                                 kappa,
                                 cell_matrix);
              constraints.distribute_local_to_global(cell_matrix,
                                                     dof_indices,
                                                     damage_system.matrix());
            }
        damage_system.matrix().compress(VectorOperation::add);
        return;
      }

    // The load of every step: no FEValues, since the shape values are those
    // of the reference cell, the Gauss-Lobatto masses and the positions of
    // the nodes in the ghosted vector are kept per cell (see
    // setup_mass_and_bounds()) and the JxW of the Gauss points with the
    // stress history.
    const double             k       = time_discretization.step_size();
    const unsigned int       n_shape = shape.size();
    const FullMatrix<double> psi_gauss
      = reference_shape_values(fe, shape, quadrature);
    const double       *damage_values = damage.begin();
    Vector<double>      cell_rhs(n_shape);
    std::vector<double> old_nodal(n_shape);
    // The cells whose nodes are all owned and not hanging (all of them on
    // one rank without hanging nodes) add their load to the owned vector
    // by position, in the order of the cells, as distribute_local_to_global
    // would, without its index lookups; the others go through the
    // constraints and the ghosted assembly vector, whose owned part is then
    // added.
    damage_load          = 0.;
    damage_load_assembly = 0.;
    double *const load   = damage_load.begin();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int first = cell->active_cell_index() * n_shape;
          for (unsigned int a = 0; a < n_shape; ++a)
            old_nodal[a] = damage_values[damage_cell_positions[first + a]];
          damage_cell_load(&damage_cell_mass[first],
                           old_nodal,
                           psi_gauss,
                           std::as_const(stress_history).JxW(cell),
                           std::as_const(stress_history).get_data(cell),
                           k,
                           cell_rhs);
          if (damage_cell_owned[first] >= 0)
            for (unsigned int a = 0; a < n_shape; ++a)
              load[damage_cell_owned[first + a]] += cell_rhs(a);
          else
            {
              damage_system.dof_indices(cell, dof_indices);
              constraints.distribute_local_to_global(cell_rhs,
                                                     dof_indices,
                                                     damage_load_assembly);
            }
        }
    damage_load_assembly.compress(VectorOperation::add);
    const double *const assembled = damage_load_assembly.begin();
    for (unsigned int i = 0; i < damage_load.locally_owned_size(); ++i)
      load[i] += assembled[i];
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
