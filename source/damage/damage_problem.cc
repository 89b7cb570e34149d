// The damage problem's setup, initial damage and assembly: its degrees of
// freedom, the lumped mass and the bounds, zeta_0, the matrix
// M_L/k + kappa A (once per mesh) and the load of every step (its solve is
// in damage_problem_solve.cc).
#include <vpcontact/damage/damage_problem.h>
#include <vpcontact/fe/discretization.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/finite_values.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace VPContact
{
  namespace
  {
    // The element matrix M_L/k + kappa A of the damage problem on one cell,
    // on its damage shape functions @p shape: the mass with the
    // vertex rule (lumped), the diffusion with the rule of the stress history.
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
    // lumped mass term is the cell's vertex-rule mass @p cell_mass of each
    // node times its zeta_{n-1} (@p old_nodal): at the vertices
    // psi_a(x_b) = delta_ab, so the rule collapses to one term per node. The
    // source is stored at the Gauss points by the assembly of the
    // displacement step, integrated with the shape values @p psi_gauss of
    // reference_shape_values() and the JxW stored with it.
    void
    damage_cell_load(const double                  *cell_mass,
                     const std::vector<double>     &old_nodal,
                     const FullMatrix<double>      &psi_gauss,
                     const ArrayView<const double> &JxW,
                     const ArrayView<const double> &source,
                     const double                   k,
                     Vector<double>                &cell_rhs)
    {
      const unsigned int n_shape = old_nodal.size();
      for (unsigned int a = 0; a < n_shape; ++a)
        cell_rhs(a) = cell_mass[a] * old_nodal[a] / k;
      for (unsigned int q = 0; q < JxW.size(); ++q)
        {
          const double weight = source[q] * JxW[q];
          for (unsigned int a = 0; a < n_shape; ++a)
            cell_rhs(a) += psi_gauss(q, a) * weight;
        }
    }
  } // namespace



  template <int dim>
  void
  DamageProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    DamageSystem<dim>::declare_parameters(prm);
  }



  template <int dim>
  DamageProblem<dim>::DamageProblem(ParameterHandler         &prm,
                                    const DamageModel<dim>   &model,
                                    const TimeDiscretization &time,
                                    const LinearSolver       &linear_solver,
                                    const std::string        &output_directory,
                                    TimerOutput              &timer,
                                    const MPI_Comm            communicator)
    : model(model)
    , time(time)
    , linear_solver(linear_solver)
    , output_directory(output_directory)
    , timer(timer)
    , communicator(communicator)
  {
    system.parse_parameters(prm, linear_solver.package());
  }



  template <int dim>
  void
  DamageProblem<dim>::setup(const DoFHandler<dim> &dof_handler_in,
                            const Quadrature<dim> &quadrature_in,
                            const IndexSet        &locally_owned_dofs,
                            const IndexSet        &locally_relevant_dofs,
                            LA::MPI::BlockVector  &solution_owned)
  {
    TimerOutput::Scope t(timer, "Setup");
    dof_handler = &dof_handler_in;
    quadrature  = &quadrature_in;
    // The bound sets and counters of an earlier mesh must not survive into
    // this one.
    bounds            = DamageBounds();
    rings_ahead       = 0;
    last_iterations   = 0;
    last_clip         = 0;
    largest_violation = 0;
    model.check_diffusion_length(
      GridTools::minimal_cell_diameter(dof_handler->get_triangulation(),
                                       get_default_linear_mapping(
                                         dof_handler->get_triangulation())),
      time.step_size());
    system.reinit(*dof_handler,
                  dim,
                  locally_owned_dofs,
                  locally_relevant_dofs,
                  communicator);
    const IndexSet &owned    = system.owned();
    const IndexSet &relevant = system.relevant();
    for (auto *v : {&old_damage,
                    &damage_owned,
                    &change,
                    &solve_rhs,
                    &load,
                    &residual_owned,
                    &bound_change})
      v->reinit(owned, communicator);
    damage.reinit(owned, relevant, communicator);
    residual.reinit(owned, relevant, communicator);
    load_assembly.reinit(owned, relevant, communicator, true);

    setup_mass_and_bounds();
    interpolate_initial_damage(solution_owned);

    // K = M_L/k + kappa A does not change while the mesh and k do: it is
    // assembled and its preconditioner built once. The bounds are applied by
    // masking (see DamageSystem::solve()), not by reassembly.
    assemble_matrix();
    system.initialize_preconditioner();

    // The bound iteration's complementarity test is scaled by the matrix
    // diagonal, which the mass dominates on coarse meshes and the diffusion
    // on fine ones (see DamageBounds::set_complementarity_scale()).
    LA::MPI::Vector  diagonal(system.owned(), communicator);
    const OwnedRows &rows = system.support().rows();
    for (unsigned int i = 0; i < rows.n_rows(); ++i)
      diagonal.begin()[i] = rows.diagonal(i);
    LA::MPI::Vector ghosted(system.owned(), system.relevant(), communicator);
    ghosted = diagonal;
    bounds.set_complementarity_scale(ghosted);
  }



  template <int dim>
  void
  DamageProblem<dim>::setup_mass_and_bounds()
  {
    // The lumped mass m_i = int psi_i: the mass matrix integrated with the
    // vertex (trapezoidal) rule, which is diagonal for Q1 and P1. On
    // adaptive meshes it is condensed like the load: a hanging node hands
    // its mass to the nodes it depends on, and carries no bound itself (its
    // value is an average of theirs, within [0, 1] when theirs are).
    const auto           &constraints = system.hanging_node_constraints();
    const auto           &shape       = system.shape_functions();
    const Quadrature<dim> lobatto
      = vertex_quadrature<dim>(dof_handler->get_fe().reference_cell());
    FEValues<dim>                        fe_values(get_default_linear_mapping(
                              dof_handler->get_triangulation()),
                            dof_handler->get_fe(),
                            lobatto,
                            update_values | update_JxW_values);
    std::vector<types::global_dof_index> dof_indices;
    Vector<double>                       local_mass(shape.size());
    LA::MPI::Vector                      mass;
    mass.reinit(system.owned(), system.relevant(), communicator, true);
    const unsigned int n_entries
      = dof_handler->get_triangulation().n_active_cells() * shape.size();
    cell_mass.assign(n_entries, 0.);
    cell_positions.assign(n_entries, 0);
    cell_owned.assign(n_entries, -1);
    plain_cells.clear();
    other_cells.clear();
    for (const auto &cell : dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          system.dof_indices(cell, dof_indices);
          local_mass = 0.;
          for (unsigned int a = 0; a < shape.size(); ++a)
            for (const unsigned int q : fe_values.quadrature_point_indices())
              local_mass(a)
                += fe_values.shape_value(shape[a], q) * fe_values.JxW(q);
          constraints.distribute_local_to_global(local_mass, dof_indices, mass);
          store_cell_mass(cell, dof_indices, local_mass);
        }
    mass.compress(VectorOperation::add);
    load_through_assembly
      = Utilities::MPI::max(static_cast<unsigned int>(!other_cells.empty()),
                            communicator)
        > 0;
    lumped_mass.reinit(system.owned(), system.relevant(), communicator);
    lumped_mass = mass;
    IndexSet bounded_dofs(system.relevant().size());
    for (const auto dof : system.relevant())
      if (!constraints.is_constrained(dof))
        bounded_dofs.add_index(dof);
    bounded_dofs.compress();
    bounds.setup(bounded_dofs, system.owned(), lumped_mass, communicator);
  }



  template <int dim>
  void
  DamageProblem<dim>::store_cell_mass(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const std::vector<types::global_dof_index>           &dof_indices,
    const Vector<double>                                 &local_mass)
  {
    // What the load of every step reads of this cell (see cell_mass,
    // cell_positions and cell_owned).
    const unsigned int     n_shape     = dof_indices.size();
    const unsigned int     first       = cell->active_cell_index() * n_shape;
    const Epetra_BlockMap &ghosted_map = damage.trilinos_vector().Map();
    const IndexSet        &owned       = system.owned();
    const auto            &constraints = system.hanging_node_constraints();
    bool                   plain       = true;
    for (unsigned int a = 0; a < n_shape; ++a)
      {
        cell_mass[first + a]      = local_mass(a);
        cell_positions[first + a] = ghosted_map.LID(
          static_cast<TrilinosWrappers::types::int_type>(dof_indices[a]));
        plain = plain && owned.is_element(dof_indices[a])
                && !constraints.is_constrained(dof_indices[a]);
      }
    if (plain)
      {
        for (unsigned int a = 0; a < n_shape; ++a)
          cell_owned[first + a] = owned.index_within_set(dof_indices[a]);
        plain_cells.push_back(cell->active_cell_index());
      }
    else
      other_cells.push_back(cell);
  }



  template <int dim>
  void
  DamageProblem<dim>::setup_on_mesh(const SimulatorAccess<dim> &simulator,
                                    LA::MPI::BlockVector       &solution_owned)
  {
    setup(simulator.dof_handler,
          simulator.quadrature,
          simulator.locally_owned_dofs,
          simulator.locally_relevant_dofs,
          solution_owned);
  }



  template <int dim>
  bool
  DamageProblem<dim>::solves_in_step() const
  {
    return true;
  }



  template <int dim>
  bool
  DamageProblem<dim>::reports_before_errors() const
  {
    return true;
  }



  template <int dim>
  std::vector<std::string>
  DamageProblem<dim>::solution_field_names() const
  {
    return {"damage"};
  }



  template <int dim>
  void
  DamageProblem<dim>::interpolate_initial_damage(
    LA::MPI::BlockVector &solution_owned)
  {
    // zeta_0, checked against the bounds at every node. A constant (the
    // default 1, sound material) is its own interpolant at every node of a
    // Lagrange element: the vector takes it without evaluating the
    // expression at each node's support point, which on a fine mesh is a
    // pass over all cells with a mapping.
    if (const std::optional<double> value = model.constant_initial_damage())
      damage_owned = *value;
    else
      {
        const unsigned int n_components = dof_handler->get_fe().n_components();
        VectorFunctionFromScalarFunctionObject<dim> initial(
          [&](const Point<dim> &p) { return model.initial_damage().value(p); },
          dim,
          n_components);
        ComponentMask damage_mask(n_components, false);
        damage_mask.set(dim, true);
        LA::MPI::Vector interpolated(solution_owned.locally_owned_elements(),
                                     communicator);
        VectorTools::interpolate(*dof_handler,
                                 initial,
                                 interpolated,
                                 damage_mask);
        system.gather(interpolated, damage_owned);
      }
    system.distribute_hanging_nodes(damage_owned);
    // A NaN compares false with everything and would pass the range check
    // below unseen.
    model.check_initial_damage_finite(all_finite(damage_owned, communicator));
    const auto [lowest, highest] = range(damage_owned);
    VPContactCheckParameter(lowest >= 0 && highest <= 1,
                            "Damage/Initial damage",
                            "[" + to_text(lowest) + ", " + to_text(highest)
                              + "] (range at the nodes)",
                            "the damage must lie in [0, 1] (1 is sound).");
    copy_owned_values(damage_owned, solution_owned.block(1));
    damage_exchange.copy(damage_owned, damage);
  }



  template <int dim>
  std::pair<double, double>
  DamageProblem<dim>::range(const LA::MPI::Vector &v) const
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
    return {Utilities::MPI::min(lowest, communicator),
            Utilities::MPI::max(highest, communicator)};
  }



  template <int dim>
  void
  DamageProblem<dim>::assemble_matrix()
  {
    TimerOutput::Scope t(timer, "Damage assembly");
    // K = M_L/k + kappa A: the lumped mass M_L (vertex rule, where
    // psi_i psi_j vanishes for i != j) and the diffusion, condensed on
    // hanging nodes only: the bounds are imposed by the solver.
    const auto           &shape       = system.shape_functions();
    const auto           &constraints = system.hanging_node_constraints();
    const Quadrature<dim> lobatto
      = vertex_quadrature<dim>(dof_handler->get_fe().reference_cell());
    const Mapping<dim> &mapping
      = get_default_linear_mapping(dof_handler->get_triangulation());
    FEValues<dim>      fe_values(mapping,
                            dof_handler->get_fe(),
                            *quadrature,
                            update_gradients | update_JxW_values);
    FEValues<dim>      lobatto_values(mapping,
                                 dof_handler->get_fe(),
                                 lobatto,
                                 update_values | update_JxW_values);
    FullMatrix<double> cell_matrix(shape.size(), shape.size());
    std::vector<types::global_dof_index> dof_indices;
    system.matrix() = 0.;
    for (const auto &cell : dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          lobatto_values.reinit(cell);
          system.dof_indices(cell, dof_indices);
          damage_cell_matrix(fe_values,
                             lobatto_values,
                             shape,
                             time.step_size(),
                             model.diffusion(),
                             cell_matrix);
          constraints.distribute_local_to_global(cell_matrix,
                                                 dof_indices,
                                                 system.matrix());
        }
    system.matrix().compress(VectorOperation::add);
  }



  template <int dim>
  void
  DamageProblem<dim>::assemble_load(const StressHistory<dim> &history)
  {
    TimerOutput::Scope t(timer, "Damage assembly");
    // b = M_L zeta_{n-1}/k + (phi_{n-1}, psi), with zeta_{n-1} from the
    // ghosted vector damage and the source stored at the Gauss points by
    // the displacement step's assembly. No FEValues and no cell iterators:
    // the shape values are those of the reference cell, the vertex-rule
    // masses and the positions of the nodes in the ghosted vector are kept
    // per cell (see setup_mass_and_bounds()) and the JxW and the source of
    // the Gauss points with the stress history, all by active cell index.
    // The cells whose nodes are all owned and not hanging (all of them on
    // one rank without hanging nodes) add their load to the owned vector by
    // position, in the order of the cells, as distribute_local_to_global
    // would, without its index lookups; the others go through the
    // constraints and the ghosted assembly vector, whose owned part is then
    // added.
    const auto              &shape   = system.shape_functions();
    const unsigned int       n_shape = shape.size();
    const FullMatrix<double> psi_gauss
      = reference_shape_values(dof_handler->get_fe(), shape, *quadrature);
    const double       *damage_values = damage.begin();
    const double        k             = time.step_size();
    Vector<double>      cell_rhs(n_shape);
    std::vector<double> old_nodal(n_shape);
    double *const       owned_load = load.begin();
    const auto          load_of    = [&](const unsigned int index) {
      const unsigned int first = index * n_shape;
      for (unsigned int a = 0; a < n_shape; ++a)
        old_nodal[a] = damage_values[cell_positions[first + a]];
      damage_cell_load(&cell_mass[first],
                       old_nodal,
                       psi_gauss,
                       history.JxW(index),
                       history.damage_sources(index),
                       k,
                       cell_rhs);
      return first;
    };
    load = 0.;
    for (const unsigned int index : plain_cells)
      {
        const unsigned int first = load_of(index);
        for (unsigned int a = 0; a < n_shape; ++a)
          owned_load[cell_owned[first + a]] += cell_rhs(a);
      }
    if (!load_through_assembly)
      return;
    std::vector<types::global_dof_index> dof_indices;
    load_assembly = 0.;
    for (const auto &cell : other_cells)
      {
        load_of(cell->active_cell_index());
        system.dof_indices(cell, dof_indices);
        system.hanging_node_constraints()
          .distribute_local_to_global(cell_rhs, dof_indices, load_assembly);
      }
    load_assembly.compress(VectorOperation::add);
    const double *const assembled = load_assembly.begin();
    for (unsigned int i = 0; i < load.locally_owned_size(); ++i)
      owned_load[i] += assembled[i];
  }



  template class DamageProblem<2>;
  template class DamageProblem<3>;
} // namespace VPContact
