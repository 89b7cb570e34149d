// The simulator's mesh, degrees of freedom, constraints and sparsity.
#include <vpcontact/input_error.h>
#include <vpcontact/rigid_motions.h>
#include <vpcontact/simulator.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::make_mesh()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    if (checkpointing.resume())
      load_checkpoint_mesh();
    else
      geometry.create_mesh(triangulation);
    boundary_conditions.check_against_mesh(
      Geometry<dim>::boundary_ids_of(triangulation));
    if (boundary_conditions.has_contact_boundary())
      {
        std::vector<double> times;
        for (unsigned int n = 0; n <= time_discretization.n_steps(); ++n)
          times.push_back(time_discretization.time(n));
        const double g_max
          = friction.check_bound(triangulation,
                                 boundary_conditions.contact_boundary_ids(),
                                 times);
        // g = 0 everywhere is frictionless sliding: no active set at all.
        friction_active = (g_max > 0);
        AssertThrow(!(friction_active && viscoplasticity.implicit()),
                    ExcMessage(
                      "Viscoplasticity/Time integration = implicit is not "
                      "combined with Tresca friction in this release (the "
                      "friction bound is up to "
                      + to_text(g_max)
                      + "). Use the explicit step with a Time step within its "
                        "stability limit, or a frictionless contact "
                        "(Contact/Friction bound = 0)."));
        AssertThrow(dim == 2 || !friction_active,
                    ExcMessage(
                      "Contact/Friction bound: Tresca friction is implemented "
                      "in 2D only (in 3D the slip direction needs the "
                      "semismooth Newton method of Hueber, Stadler and "
                      "Wohlmuth, not written yet). This 3D scene has a "
                      "friction bound up to "
                      + to_text(g_max)
                      + " on its contact boundary: set it to 0 "
                        "(frictionless bilateral contact) or run in 2D."));
      }
  }



  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    TimerOutput::Scope t(computing_timer, "Setup");
    // Sets of an earlier mesh (a previous refinement cycle) name degrees of
    // freedom that no longer exist; the constraints below must not see them.
    friction_active_set = FrictionActiveSet<dim>();
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);
    // One constant mode per component for ML, the damage included: in each
    // of the two systems the rows of the other field are decoupled (held),
    // and a near-null-space vector that vanishes on them leaves ML with
    // empty aggregates there.
    DoFTools::extract_constant_modes(dof_handler,
                                     ComponentMask(fe.n_components(), true),
                                     all_constant_modes);

    // The constraints at t = 0 have the structure of those of every step
    // (only inhomogeneities of prescribed displacements change), so the
    // matrix built with them serves the whole run.
    make_constraints(0., nullptr);

    // The sparsity pattern of step-40: built on the locally relevant rows,
    // then the entries of rows owned by other ranks are sent to them.
    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    linear_solver.clear(); // it refers to the matrix of the last mesh
    stiffness_matrix.reinit(locally_owned_dofs,
                            locally_owned_dofs,
                            dsp,
                            mpi_communicator);

    // The contact nodes are read off the constraints without friction; the
    // sparsity pattern above, built with those, also holds every pattern
    // with more nodes constrained. All nodes start in the stick set.
    if (friction_active)
      {
        friction_active_set.setup(dof_handler,
                                  constraints,
                                  boundary_conditions.contact_boundary_ids(),
                                  locally_relevant_dofs);
        make_constraints(0., nullptr);

        // The multipliers are read at the contact nodes only, so the
        // residual is assembled only on the cells that hold one.
        contact_cells.clear();
        const IndexSet contact_dofs
          = friction_active_set.node_dofs(dof_handler.n_dofs());
        std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dof_indices);
              if (std::any_of(dof_indices.begin(),
                              dof_indices.end(),
                              [&](const auto dof) {
                                return contact_dofs.is_element(dof);
                              }))
                contact_cells.push_back(cell);
            }
        residual_assembly.reinit(locally_owned_dofs,
                                 locally_relevant_dofs,
                                 mpi_communicator,
                                 true);
        residual.reinit(locally_owned_dofs,
                        locally_relevant_dofs,
                        mpi_communicator);
      }

    // With all contact nodes in the stick set, the constraints now hold
    // the body as firmly as they ever will.
    check_rigid_motions_held(
      dof_handler,
      constraints,
      "Hold it with a boundary of Boundary conditions/Clamped boundary ids, "
      "Roller boundary ids or Prescribed displacement boundary ids, or with "
      "friction on the contact boundary (Contact/Friction bound > 0).");

    rhs.reinit(locally_owned_dofs, mpi_communicator);
    find_plain_rhs_cells();
    solution_owned.reinit(locally_owned_dofs, mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    increment_owned.reinit(locally_owned_dofs, mpi_communicator);
    increment_predictor.reinit(locally_owned_dofs, mpi_communicator);
    newton_update.reinit(locally_owned_dofs, mpi_communicator);
    increment.reinit(locally_owned_dofs,
                     locally_relevant_dofs,
                     mpi_communicator);
  }



  template <int dim>
  void
  Simulator<dim>::make_constraints(
    const double                         time,
    const TrilinosWrappers::MPI::Vector *previous)
  {
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    boundary_conditions.make_constraints(dof_handler,
                                         constraints,
                                         time,
                                         previous);
    if (friction_active)
      friction_active_set.add_stick_constraints(constraints);
    // The displacement step leaves the damage alone: its increment is held
    // at zero there.
    if (damage_model.is_active())
      for (const auto dof : relevant_dofs_of_components(dim, dim + 1))
        if (!constraints.is_constrained(dof))
          constraints.add_line(dof);
    constraints.close();
  }



  template <int dim>
  void
  Simulator<dim>::find_plain_rhs_cells()
  {
    // assemble_rhs() visits every cell in every step, and on most cells
    // AffineConstraints::distribute_local_to_global() only looks up that
    // no degree of freedom is constrained and adds by global index. On the
    // cells found here the right-hand side is added by position instead.
    // Every constraint that changes in time (Dirichlet, prescribed
    // displacement, contact, stick) sits on the boundary, and the hanging
    // node constraints are those of the mesh, in the constraints now, so a
    // cell with no displacement degree of freedom on the boundary or
    // constrained now stays plain while the mesh does. The damage degrees
    // of freedom are all constrained in this system and take nothing.
    // (Q1: the degrees of freedom sit at the vertices.)
    std::vector<bool> on_boundary(triangulation.n_vertices(), false);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (const unsigned int v : face->vertex_indices())
              on_boundary[face->vertex_index(v)] = true;

    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    const unsigned int invalid       = numbers::invalid_unsigned_int;
    plain_rhs_cell.assign(triangulation.n_active_cells(), false);
    plain_rhs_positions.assign(triangulation.n_active_cells() * dofs_per_cell,
                               invalid);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          bool plain = true;
          for (const unsigned int v : cell->vertex_indices())
            plain = plain && !on_boundary[cell->vertex_index(v)];
          cell->get_dof_indices(dof_indices);
          const unsigned int c = cell->active_cell_index();
          for (unsigned int i = 0; i < dofs_per_cell && plain; ++i)
            if (fe.system_to_component_index(i).first < dim)
              {
                const auto dof = dof_indices[i];
                plain          = locally_owned_dofs.is_element(dof)
                        && !constraints.is_constrained(dof);
                if (plain)
                  plain_rhs_positions[c * dofs_per_cell + i]
                    = locally_owned_dofs.index_within_set(dof);
              }
          plain_rhs_cell[c] = plain;
        }
    split_plain_rhs_cells();
  }



  template <int dim>
  void
  Simulator<dim>::split_plain_rhs_cells()
  {
    // assemble_rhs() adds the plain cells of each half by position in a
    // thread of its own: a cell of the second half that adds to an entry
    // that a cell of the first half adds to is left to the calling thread,
    // after both halves, with the cells that are not plain (about one row
    // of cells along the cut, and the boundary).
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
    std::vector<typename DoFHandler<dim>::active_cell_iterator> plain_cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && plain_rhs_cell[cell->active_cell_index()])
        plain_cells.push_back(cell);
    const auto middle = plain_cells.begin() + plain_cells.size() / 2;
    rhs_halves[0].assign(plain_cells.begin(), middle);
    rhs_halves[1].clear();

    std::vector<bool> first_half_entry(locally_owned_dofs.n_elements(), false);
    const auto        positions = [&](const auto &cell) {
      const unsigned int *first = plain_rhs_positions.data()
                                  + cell->active_cell_index() * dofs_per_cell;
      return make_array_view(first, first + dofs_per_cell);
    };
    for (const auto &cell : rhs_halves[0])
      for (const unsigned int position : positions(cell))
        if (position != numbers::invalid_unsigned_int)
          first_half_entry[position] = true;
    std::vector<bool> serial(triangulation.n_active_cells(), false);
    for (auto cell = middle; cell != plain_cells.end(); ++cell)
      {
        bool shared = false;
        for (const unsigned int position : positions(*cell))
          shared = shared
                   || (position != numbers::invalid_unsigned_int
                       && first_half_entry[position]);
        if (shared)
          serial[(*cell)->active_cell_index()] = true;
        else
          rhs_halves[1].push_back(*cell);
      }
    rhs_serial_cells.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned()
          && (!plain_rhs_cell[cell->active_cell_index()]
              || serial[cell->active_cell_index()]))
        rhs_serial_cells.push_back(cell);
  }



  template <int dim>
  void
  Simulator<dim>::setup_stress_history()
  {
    // sigma_0 = 0 at every quadrature point of every locally owned cell;
    // compute_initial_state() replaces it where the scene asks for elastic
    // equilibrium. The JxW of the points are stored with them, and the
    // shape gradients in cell_kinematics, once per mesh (see StressHistory
    // and CellKinematics).
    stress_history.clear();
    FEValues<dim> fe_values(fe, quadrature, update_JxW_values);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          stress_history.initialize(cell, quadrature.size());
          fe_values.reinit(cell);
          stress_history.set_JxW(cell, fe_values.get_JxW_values());
        }
    cell_kinematics.reinit(dof_handler, quadrature, solution);
    cell_halves.reinit(dof_handler);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
