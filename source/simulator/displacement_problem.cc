// The displacement problem's parameters, its setup on a mesh (Tresca
// friction, constraints, the matrix's sparsity, vectors, the stress
// history), and the checks of its input: the stability of the explicit
// step, and a body that the slipping contact no longer holds.
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/problem_data/geometry.h>
#include <vpcontact/problem_data/rigid_motions.h>
#include <vpcontact/simulator/displacement_problem.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <cmath>

namespace VPContact
{
  template <int dim>
  void
  DisplacementProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    ElasticMaterial<dim>::declare_parameters(prm);
    ViscoplasticityParameters<dim>::declare_parameters(prm);
    BoundaryConditions<dim>::declare_parameters(prm);
    TrescaFriction<dim>::declare_parameters(prm);
    LinearSolver::declare_parameters(prm);
    IncrementPredictor::declare_parameters(prm);
  }



  template <int dim>
  DisplacementProblem<dim>::DisplacementProblem(
    ParameterHandler           &prm,
    const SimulatorAccess<dim> &access)
    : SimulatorAccess<dim>(access)
  {
    material.parse_parameters(prm);
    viscoplasticity.parse_parameters(prm);
    viscoplastic_law = viscoplasticity.create_law(prm);
    boundary_conditions.parse_parameters(prm);
    friction.parse_parameters(prm);
    displacement.solver.parse_parameters(prm);
    increment_predictor.parse_parameters(prm);
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first < dim)
        displacement.shape_functions.push_back(i);
  }



  template <int dim>
  DisplacementProblem<dim>::~DisplacementProblem()
  {
    // Members are destroyed in reverse order of declaration, the matrices
    // before the linear solver; a factorization (MUMPS) must go first.
    displacement.solver.clear();
  }



  template <int dim>
  Physics<dim> *
  DisplacementProblem<dim>::setup_contact(const std::string &mesh_source)
  {
    boundary_conditions.check_against_mesh(Geometry<dim>::boundary_ids_of(
                                             triangulation),
                                           mesh_source);
    friction_problem.reset();
    if (!boundary_conditions.has_contact_boundary())
      return nullptr;
    std::vector<double> times;
    for (unsigned int n = 0; n <= time_discretization.n_steps(); ++n)
      times.push_back(time_discretization.time(n));
    const double g_max
      = friction.check_bound(triangulation,
                             boundary_conditions.contact_boundary_ids(),
                             times);
    largest_friction = g_max;
    // Bilateral contact with g = 0 everywhere is frictionless sliding: no
    // active set at all.
    if (friction.needs_active_set(g_max))
      friction_problem
        = std::make_unique<FrictionProblem<dim>>(friction, mpi_communicator);
    AssertThrow(!(friction_problem && viscoplasticity.implicit()),
                ExcMessage(
                  "Viscoplasticity/Time integration = implicit is not "
                  "combined with friction or unilateral contact in this "
                  "release (the friction bound or coefficient is up to "
                  + to_text(g_max)
                  + "). Use the explicit step with a Time step within its "
                    "stability limit, or a frictionless bilateral contact "
                    "(Contact/Friction bound = 0)."));
    return friction_problem.get();
  }



  template <int dim>
  void
  DisplacementProblem<dim>::measure_body()
  {
    // The diagonal of the body's bounding box over all ranks: the scale of
    // displacement_limit() on this mesh.
    const auto box   = GridTools::compute_bounding_box(triangulation);
    Point<dim> lower = box.get_boundary_points().first,
               upper = box.get_boundary_points().second;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = Utilities::MPI::min(lower[d], mpi_communicator);
        upper[d] = Utilities::MPI::max(upper[d], mpi_communicator);
      }
    body_size = lower.distance(upper);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::setup_block_views()
  {
    // The displacement block [0, n_u) of the block numbering.
    std::vector<unsigned int> block_component(fe.n_components(), 0);
    if (fe.n_components() > dim)
      block_component[dim] = 1;
    const types::global_dof_index n_u
      = DoFTools::count_dofs_per_fe_block(dof_handler, block_component)[0];
    displacement.owned    = locally_owned_dofs.get_view(0, n_u);
    displacement.relevant = locally_relevant_dofs.get_view(0, n_u);
    // (Cholesky factorizes in the one process of the whole job only.)
    displacement.solver.choose(n_u,
                               dim,
                               Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD),
                               time_discretization.n_steps());
  }



  template <int dim>
  void
  DisplacementProblem<dim>::setup_dofs()
  {
    // Sets of an earlier mesh (a previous refinement cycle) name degrees of
    // freedom that no longer exist; the constraints below must not see them.
    if (friction_problem)
      friction_problem->clear();
    // The owned cells, over which the matrix and every pass over the cells
    // run.
    owned_cells.clear();
    rhs_chunks.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        owned_cells.push_back(cell);
    measure_body();
    setup_block_views();
    // The constraints at t = 0 have the structure of those of every step
    // (only inhomogeneities of prescribed displacements change): the
    // matrix built with them serves the whole run.
    make_constraints(0., nullptr);
    setup_displacement_matrix();

    // The contact nodes are read off the constraints without friction; the
    // sparsity pattern built with those holds every pattern with more nodes
    // constrained. All nodes start in the stick set. What these constraints
    // leave free is what the body keeps once every contact node slips.
    const RigidMotionCheck<dim> rigid_motion_check(dof_handler);
    if (friction_problem)
      {
        friction_problem->setup(dof_handler,
                                constraints,
                                boundary_conditions.contact_boundary_ids(),
                                locally_owned_dofs,
                                locally_relevant_dofs);
        // With unilateral contact, every node in contact and none sticking.
        make_constraints(0., nullptr, false);
        const auto  free  = rigid_motion_check.free_motions(constraints);
        const auto &parts = rigid_motion_check.parts();
        friction_problem->set_motion_free_when_all_slip(
          free.empty()         ? std::string() :
          parts.n_parts() == 1 ? free.front().second :
                                 free.front().second + " of "
                                   + parts.description(free.front().first));
        make_constraints(0., nullptr);
        contact_residual.reinit(locally_owned_dofs,
                                locally_relevant_dofs,
                                mpi_communicator,
                                true);
      }

    // With all contact nodes in the stick set, the constraints now hold
    // the body, and each part of its mesh, as firmly as they ever will.
    rigid_motion_check.assert_held(
      constraints,
      "Hold it with a boundary of Boundary conditions/Clamped boundary ids, "
      "Roller boundary ids or Prescribed displacement boundary ids, or with "
      "friction on the contact boundary (Contact/Friction bound > 0).");

    setup_vectors();
  }



  template <int dim>
  void
  DisplacementProblem<dim>::setup_vectors()
  {
    // The owned vectors in blocks: the linear solver works on the
    // displacement block of the increment in place.
    const types::global_dof_index n_u = displacement.owned.size();
    std::vector<IndexSet>         blocks{displacement.owned};
    if (dof_handler.n_dofs() > n_u)
      blocks.push_back(locally_owned_dofs.get_view(n_u, dof_handler.n_dofs()));
    displacement.rhs.reinit(displacement.owned, mpi_communicator);
    solution_owned.reinit(blocks, mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    increment_owned.reinit(blocks, mpi_communicator);
    increment_predictor.reinit(displacement.owned, mpi_communicator);
    increment.reinit(locally_owned_dofs,
                     locally_relevant_dofs,
                     mpi_communicator);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::setup_displacement_matrix()
  {
    // The sparsity pattern of the displacement block: Trilinos sends the
    // entries of rows that other ranks own to them (as in step-32).
    LA::SparsityPattern                  sparsity(displacement.owned,
                                 displacement.owned,
                                 displacement.relevant,
                                 mpi_communicator);
    std::vector<types::global_dof_index> u_indices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          get_displacement_dof_indices(cell, u_indices);
          constraints.add_entries_local_to_global(u_indices, sparsity, false);
        }
    sparsity.compress();
    // The solver refers to the matrix and the rigid motions of the last
    // mesh.
    displacement.solver.clear();
    displacement.matrix.reinit(sparsity);
    displacement.rigid_motions = NearNullSpace();
  }



  template <int dim>
  void
  DisplacementProblem<dim>::make_constraints(const double           time,
                                             const LA::MPI::Vector *previous,
                                             const bool             with_stick)
  {
    // On the displacement block only: the damage problem keeps the hanging
    // node constraints of its own block (DamageSystem).
    constraints.clear();
    constraints.reinit(displacement.relevant);
    add_displacement_hanging_nodes();
    boundary_conditions.make_constraints(dof_handler,
                                         constraints,
                                         time,
                                         previous,
                                         !friction.unilateral());
    if (friction_problem)
      friction_problem->add_constraints(constraints, previous, with_stick);
    constraints.close();
  }



  template <int dim>
  void
  DisplacementProblem<dim>::add_displacement_hanging_nodes()
  {
    // deal.II makes them for every component; the damage's are left out.
    // A displacement node hangs on displacement nodes only.
    AffineConstraints<double> all(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, all);
    const types::global_dof_index n_u = displacement.owned.size();
    for (const auto &line : all.get_lines())
      if (line.index < n_u)
        {
          constraints.add_line(line.index);
          constraints.add_entries(line.index, line.entries);
        }
  }



  template <int dim>
  void
  DisplacementProblem<dim>::get_displacement_dof_indices(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                 &indices) const
  {
    // Called for every cell in every step, from several threads: each
    // thread keeps its own vector instead of allocating one per call.
    thread_local std::vector<types::global_dof_index> all;
    all.resize(fe.n_dofs_per_cell());
    cell->get_dof_indices(all);
    indices.resize(displacement.shape_functions.size());
    for (unsigned int i = 0; i < indices.size(); ++i)
      indices[i] = all[displacement.shape_functions[i]];
  }



  template <int dim>
  NearNullSpace
  DisplacementProblem<dim>::rigid_motions() const
  {
    // The rigid motions of the body at the displacement nodes, about the
    // centre of its bounding box (for better conditioned vectors): dim
    // translations and 1 (2D) or 3 (3D) rotations, for AMG's near null
    // space.
    NearNullSpace space;
    space.dofs_per_node = dim;
    const Point<dim> centre
      = GridTools::compute_bounding_box(triangulation).center();
    const unsigned int n_modes = (dim == 2 ? 3 : 6);
    space.modes.assign(n_modes,
                       LA::MPI::Vector(displacement.owned, mpi_communicator));
    // One pass over the owned cells, which hold every owned node: the
    // support points of a cell's shape functions are its quadrature points
    // for the quadrature made of them. A node shared by several cells is
    // written by each, with the same values.
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            Quadrature<dim>(fe.get_unit_support_points()),
                            update_quadrature_points);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            {
              const unsigned int d = fe.system_to_component_index(i).first;
              if (d >= dim || !displacement.owned.is_element(indices[i]))
                continue;
              const Tensor<1, dim> x = fe_values.quadrature_point(i) - centre;
              space.modes[d](indices[i]) = 1.;
              // Rotation about axis a: the velocity e_a x x, component d.
              for (unsigned int a = 0; a < n_modes - dim; ++a)
                {
                  const unsigned int axis = (dim == 2 ? 2 : a);
                  Tensor<1, 3>       e, y;
                  e[axis] = 1.;
                  for (unsigned int c = 0; c < dim; ++c)
                    y[c] = x[c];
                  space.modes[dim + a](indices[i]) = cross_product_3d(e, y)[d];
                }
            }
        }
    for (auto &mode : space.modes)
      mode.compress(VectorOperation::insert);
    return space;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::setup_stress_history()
  {
    // sigma_0 = 0 at every quadrature point of every locally owned cell;
    // compute_initial_state() replaces it where the scene asks for elastic
    // equilibrium. The JxW of the points are stored with them, and the
    // shape gradients in cell_kinematics, once per mesh (see StressHistory
    // and CellKinematics).
    stress_history.clear();
    stress_sums_current = false;
    FEValues<dim> fe_values(mapping, fe, quadrature, update_JxW_values);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          stress_history.initialize(cell, quadrature.size());
          fe_values.reinit(cell);
          stress_history.set_JxW(cell, fe_values.get_JxW_values());
        }
    cell_kinematics.reinit(dof_handler, quadrature, solution);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::check_stability_limits() const
  {
    // The forward Euler step of sigma_dot = G(sigma) amplifies an error by
    // 1 - k L_G for a law with Lipschitz constant L_G; beyond k = 2 / L_G it
    // grows without bound. Refuse such a step before computing anything.
    if (viscoplasticity.implicit())
      return; // backward Euler is stable for any step
    const double k     = time_discretization.step_size();
    const double limit = viscoplastic_law->explicit_step_limit();
    VPContactCheckParameter(
      k <= limit,
      "Time/Time step",
      k,
      "the explicit (forward Euler) viscoplastic step is unstable for this "
      "law ("
        + viscoplastic_law->description() + ") when k > " + to_text(limit)
        + " (2 / Lipschitz constant of G; for Maxwell 2 eta). "
          "Choose Time step <= "
        + to_text(limit)
        + ", a slower law (larger Viscoplasticity/Relaxation time), or "
          "Viscoplasticity/Time integration = implicit.");
  }



  template <int dim>
  void
  DisplacementProblem<dim>::check_held_while_slipping(const double time)
  {
    // With no stick node left, the contact boundary holds the body only in
    // its normal direction, and the friction force g on it is fixed: a
    // rigid motion that the other constraints leave free is then free in
    // the next solve too, whose matrix is singular and whose answer, if
    // any, is a body that slides away. An iterate may pass through such
    // sets on its way to sets that hold the body (Coulomb's bounds move
    // with the pressure): the first time in a row, the node nearest to
    // sticking is kept in the stick set; the second time the load is more
    // than friction holds. Stop then, saying why.
    const std::string &motion = friction_problem->motion_free_when_all_slip();
    if (motion.empty() || friction_problem->n_stick_nodes() > 0)
      {
        kept_one_stick = false;
        return;
      }
    if (!kept_one_stick && friction_problem->keep_one_stick())
      {
        kept_one_stick = true;
        return;
      }
    const double k = time_discretization.step_size();
    AssertThrow(
      false,
      ExcMessage(
        "At t = " + to_text(time) + " (step "
        + std::to_string(static_cast<long>(std::lround(time / k)))
        + ") every contact node slips: the friction bound "
          "(Contact/Friction bound, at most "
        + to_text(friction_problem->max_bound())
        + " here) no longer holds the tangential load on the contact "
          "boundary, and nothing else holds the body against "
        + motion + " (Boundary conditions: " + boundary_conditions.summary()
        + "). The body would slide away without bound, and the "
          "quasistatic problem has no solution from here on. Raise "
          "Contact/Friction bound, or hold the body against this motion "
          "with a boundary of Boundary conditions/Clamped boundary ids, "
          "Roller boundary ids or Prescribed displacement boundary ids. "
          "The output up to the previous step is complete in "
        + output_writer.directory() + "."));
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
