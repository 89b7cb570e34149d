// The damage problem's linear algebra on the damage degrees of freedom alone.
#include <vpcontact/damage/damage_system.h>
#include <vpcontact/fe/owned_constraints.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace VPContact
{
  template <int dim>
  void
  DamageSystem<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      prm.declare_entry(
        "Damage preconditioner",
        "modified diagonal incomplete Cholesky",
        Patterns::Selection("modified diagonal incomplete Cholesky|modified "
                            "incomplete Cholesky|incomplete Cholesky|AMG"),
        "Preconditioner of the CG solves of the damage problem, M_L/k + "
        "kappa A on the nodes off the bounds. The first two are the "
        "program's own (DamageRegionSolver), for either Solver/Linear "
        "algebra: CG runs over the free nodes only, preconditioned on a "
        "region of each rank's rows around them that is kept for the whole "
        "step, so that a solve costs in proportion to the damaged part of "
        "the body. 'modified diagonal incomplete Cholesky': P = (D + L) "
        "D^{-1} (D + L^T) with L the strictly lower part of the matrix and "
        "D such that P keeps its row sums, applied with Eisenstat's trick "
        "(an iteration is two triangular sweeps, no separate product). "
        "'modified incomplete Cholesky': MIC(0), which keeps the row sums "
        "too. Both need fewer iterations than IC(0) (O(h^-1/2) against "
        "O(h^-1)). 'incomplete Cholesky': IC(0) of the free rows' "
        "submatrix from the package of Solver/Linear algebra (Ifpack, or "
        "PETSc block Jacobi with ICC), rebuilt when the free set changes. "
        "'AMG': algebraic multigrid (ML, GAMG) of the whole matrix, whose "
        "iterations do not grow with the mesh, for meshes far finer than "
        "512^2 cells or where kappa k / h^2 is large. doc/performance.md "
        "says what each costs.");
      prm.declare_entry(
        "Damage obstacle solver",
        "active set",
        Patterns::Selection("active set|SNES VI"),
        "How the bounds 0 <= zeta <= 1 of the damage problem are found. "
        "'active set': the program's primal-dual active set around the CG "
        "solves above, warm-started from the previous step's sets, with "
        "inexact solves while the sets still change (Damage/Maximum active "
        "set iterations bounds it). 'SNES VI': PETSc's reduced-space "
        "semismooth Newton method for variational inequalities "
        "(SNESVINEWTONRSLS) on the whole problem, started from zeta_{n-1}, "
        "with CG and block Jacobi / ICC on the free nodes; it needs "
        "Linear algebra = PETSc and a mesh without hanging nodes. Both "
        "solve the same discrete problem.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  DamageSystem<dim>::parse_parameters(ParameterHandler   &prm,
                                      const LinearAlgebra linear_algebra)
  {
    prm.enter_subsection("Solver");
    const std::string kind = prm.get("Damage preconditioner");
    method
      = (kind == "AMG" ? SpdMethod::cg_amg : SpdMethod::cg_incomplete_cholesky);
    use_region_solver = (kind != "AMG" && kind != "incomplete Cholesky");
    region_kind
      = (kind == "modified incomplete Cholesky" ?
           DamageRegionSolver::Preconditioner::modified_incomplete_cholesky :
           DamageRegionSolver::Preconditioner::diagonal);
    package     = linear_algebra;
    use_snes_vi = (prm.get("Damage obstacle solver") == "SNES VI");
    AssertThrow(!use_snes_vi || package == LinearAlgebra::petsc,
                ExcMessage(parameter_message(
                  "Solver/Damage obstacle solver",
                  "SNES VI",
                  "PETSc's SNES VI needs Solver/Linear algebra = PETSc "
                  "(it is Trilinos here): set both, or choose 'active set'.")));
    prm.leave_subsection();
  }



  template <int dim>
  void
  DamageSystem<dim>::reinit(const DoFHandler<dim> &dof_handler,
                            const unsigned int     component,
                            const IndexSet        &locally_owned_dofs,
                            const IndexSet        &locally_relevant_dofs,
                            const MPI_Comm         communicator)
  {
    solver.reset(); // it refers to the matrix of the last mesh
    const auto &fe = dof_handler.get_fe();
    damage_shape_functions.clear();
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      if (fe.system_to_component_index(i).first == component)
        damage_shape_functions.push_back(i);

    take_block(dof_handler, locally_owned_dofs, locally_relevant_dofs);
    make_hanging_node_constraints(dof_handler, locally_relevant_dofs);
    has_hanging_nodes = (Utilities::MPI::max(static_cast<unsigned int>(
                                               constraints.n_constraints()),
                                             communicator)
                         > 0);

    DynamicSparsityPattern               dsp(compact_relevant);
    std::vector<types::global_dof_index> indices;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dof_indices(cell, indices);
          constraints.add_entries_local_to_global(indices, dsp, false);
        }
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               compact_owned,
                                               communicator,
                                               compact_relevant);
    system_matrix.reinit(compact_owned, compact_owned, dsp, communicator);
  }



  template <int dim>
  void
  DamageSystem<dim>::take_block(const DoFHandler<dim> &dof_handler,
                                const IndexSet        &locally_owned_dofs,
                                const IndexSet        &locally_relevant_dofs)
  {
    // The FESystem is numbered by blocks (Simulator::number_dofs()): the
    // damage is the block [first, n), and a block index is the degree of
    // freedom's index less first. Each rank's owned damage entries are a
    // contiguous range, which follows its owned displacement entries in
    // the local storage of a vector on all of them.
    const types::global_dof_index n     = dof_handler.n_dofs();
    const types::global_dof_index first = n - count_damage_dofs(dof_handler);
    block_start                         = first;
    compact_owned                       = locally_owned_dofs.get_view(first, n);
    compact_relevant = locally_relevant_dofs.get_view(first, n);
    damage_dofs      = IndexSet(n);
    damage_dofs.add_range(first, n);
    damage_dofs  = damage_dofs & locally_relevant_dofs;
    owned_offset = locally_owned_dofs.n_elements() - compact_owned.n_elements();

    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    const unsigned int n_shape = damage_shape_functions.size();
    cell_dofs.assign(dof_handler.get_triangulation().n_active_cells() * n_shape,
                     numbers::invalid_dof_index);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int j = 0; j < n_shape; ++j)
            {
              const auto dof = dofs[damage_shape_functions[j]];
              Assert(dof >= first,
                     ExcMessage("The damage degrees of freedom must be the "
                                "last block (DoFRenumbering::component_wise "
                                "with the damage in block 1)."));
              cell_dofs[cell->active_cell_index() * n_shape + j] = dof - first;
            }
        }
  }



  template <int dim>
  types::global_dof_index
  DamageSystem<dim>::count_damage_dofs(const DoFHandler<dim> &dof_handler) const
  {
    // The damage element is the last base element of the FESystem, one
    // scalar component: its share of the degrees of freedom.
    std::vector<unsigned int> block_component(
      dof_handler.get_fe().n_components(),
      0);
    block_component.back() = 1;
    return DoFTools::count_dofs_per_fe_block(dof_handler, block_component)[1];
  }



  template <int dim>
  void
  DamageSystem<dim>::make_hanging_node_constraints(
    const DoFHandler<dim> &dof_handler,
    const IndexSet        &locally_relevant_dofs)
  {
    // The hanging node constraints of the FESystem, on the damage block. A
    // hanging damage node depends on damage nodes of a cell this rank sees,
    // so its parents are relevant here too.
    AffineConstraints<double> full_constraints(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, full_constraints);
    full_constraints.close();
    constraints.clear();
    constraints.reinit(compact_relevant);
    for (const auto dof : damage_dofs)
      if (full_constraints.is_constrained(dof))
        {
          const auto line = dof - block_start;
          constraints.add_line(line);
          for (const auto &[parent, weight] :
               *full_constraints.get_constraint_entries(dof))
            {
              AssertThrow(parent >= block_start, ExcInternalError());
              constraints.add_entry(line, parent - block_start, weight);
            }
        }
    constraints.close();
    hanging_positions.clear();
    for (const auto dof : compact_owned)
      if (constraints.is_constrained(dof))
        hanging_positions.push_back(local_position(dof));
  }



  template <int dim>
  const IndexSet &
  DamageSystem<dim>::owned() const
  {
    return compact_owned;
  }



  template <int dim>
  const IndexSet &
  DamageSystem<dim>::relevant() const
  {
    return compact_relevant;
  }



  template <int dim>
  const std::vector<unsigned int> &
  DamageSystem<dim>::shape_functions() const
  {
    return damage_shape_functions;
  }



  template <int dim>
  void
  DamageSystem<dim>::dof_indices(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    std::vector<types::global_dof_index>                 &indices) const
  {
    const unsigned int n_shape = damage_shape_functions.size();
    indices.resize(n_shape);
    for (unsigned int j = 0; j < n_shape; ++j)
      indices[j] = cell_dofs[cell->active_cell_index() * n_shape + j];
  }



  template <int dim>
  const AffineConstraints<double> &
  DamageSystem<dim>::hanging_node_constraints() const
  {
    return constraints;
  }



  template <int dim>
  void
  DamageSystem<dim>::distribute_hanging_nodes(
    LA::MPI::Vector &owned_vector) const
  {
    if (has_hanging_nodes)
      distribute_constraints(constraints, owned_vector);
  }



  template <int dim>
  const std::vector<unsigned int> &
  DamageSystem<dim>::hanging_node_positions() const
  {
    return hanging_positions;
  }



  template <int dim>
  unsigned int
  DamageSystem<dim>::local_position(
    const types::global_dof_index compact_index) const
  {
    return compact_index - compact_owned.nth_index_in_set(0);
  }



  template <int dim>
  void
  DamageSystem<dim>::gather(const LA::MPI::Vector &full,
                            LA::MPI::Vector       &compact) const
  {
    // The local entries of owned vectors, in the order of their index sets:
    // the damage block's follow the displacement block's (see take_block()).
    std::copy_n(full.begin() + owned_offset,
                compact.locally_owned_size(),
                compact.begin());
  }



  template <int dim>
  void
  DamageSystem<dim>::scatter(const LA::MPI::Vector &compact,
                             LA::MPI::Vector       &full) const
  {
    std::copy_n(compact.begin(),
                compact.locally_owned_size(),
                full.begin() + owned_offset);
  }



  template <int dim>
  LA::SparseMatrix &
  DamageSystem<dim>::matrix()
  {
    Assert(system_matrix.m() == compact_owned.size(),
           ExcMessage("The matrix was released: reinit() first."));
    return system_matrix;
  }



  template <int dim>
  void
  DamageSystem<dim>::initialize_preconditioner()
  {
    // SNES VI does the linear solves itself: the preconditioner of the
    // active set's solves is built only for them.
    matrix_rows.reinit(system_matrix,
                       compact_owned,
                       system_matrix.get_mpi_communicator());
    support_product.initialize(matrix_rows);
    if (!use_snes_vi && use_region_solver)
      {
        region_solver.initialize(matrix_rows, region_kind);
        // Nothing reads the Trilinos matrix any more: at 512^2 cells it is
        // 28 MB until the next mesh.
        system_matrix.clear();
      }
    else if (!use_snes_vi)
      {
        solver
          = create_spd_solver(package, method, "Solver/Damage preconditioner");
        solver->initialize(system_matrix, NearNullSpace());
      }
    else
      {
        // SNES VI sees the bounds of every node; a hanging node must
        // instead follow its parents, which the active set method holds.
        AssertThrow(!has_hanging_nodes,
                    ExcMessage(parameter_message(
                      "Solver/Damage obstacle solver",
                      "SNES VI",
                      "the mesh has hanging nodes (adaptive refinement), "
                      "which SNES VI cannot hold to their parents: choose "
                      "'active set' for this scene.")));
        if (!obstacle_snes)
          obstacle_snes = std::make_unique<DamageObstacleSnes>();
        obstacle_snes->initialize(system_matrix);
      }
  }



  template <int dim>
  void
  DamageSystem<dim>::vmult_on_support(LA::MPI::Vector       &y,
                                      const LA::MPI::Vector &x)
  {
    support_product.vmult(y, x);
  }



  template <int dim>
  void
  DamageSystem<dim>::vmult_on_rows(LA::MPI::Vector                 &y,
                                   const LA::MPI::Vector           &x,
                                   const std::vector<unsigned int> &rows)
  {
    support_product.vmult_on(y, x, rows);
  }



  template <int dim>
  const SupportProduct &
  DamageSystem<dim>::support() const
  {
    return support_product;
  }



  template <int dim>
  SupportProduct &
  DamageSystem<dim>::support()
  {
    return support_product;
  }



  template <int dim>
  void
  DamageSystem<dim>::begin_step()
  {
    region_solver.begin_step();
  }



  template <int dim>
  bool
  DamageSystem<dim>::solves_obstacle_whole() const
  {
    return use_snes_vi;
  }



  template <int dim>
  unsigned int
  DamageSystem<dim>::solve_obstacle(const LA::MPI::Vector &b,
                                    LA::MPI::Vector       &zeta,
                                    const double           tolerance,
                                    const unsigned int     max_iterations,
                                    const unsigned int max_linear_iterations)
  {
    Assert(obstacle_snes, ExcMessage("initialize_preconditioner() first."));
    return obstacle_snes->solve(b,
                                zeta,
                                tolerance,
                                max_iterations,
                                max_linear_iterations);
  }



  template <int dim>
  unsigned int
  DamageSystem<dim>::solve(const LA::MPI::Vector           &b,
                           LA::MPI::Vector                 &x,
                           const std::vector<unsigned int> &held,
                           const double                     tolerance,
                           const unsigned int               max_iterations)
  {
    // The region solver measures |b| on the free nodes itself (b vanishes
    // on the held ones) and returns x = 0 for b = 0.
    const double b_norm = (use_region_solver ? 0. : b.l2_norm());
    if (!use_region_solver && b_norm == 0.)
      {
        x = 0.;
        return 0;
      }
    SolverControl control(max_iterations, tolerance * b_norm);
    try
      {
        Assert(use_region_solver || solver,
               ExcMessage("initialize_preconditioner() first."));
        const unsigned int iterations
          = (use_region_solver ?
               region_solver.solve(b, x, held, tolerance, max_iterations) :
               solver->solve(x, b, control, held));
        work_of_solves
          += double(compact_owned.n_elements() - held.size()) * iterations;
        return iterations;
      }
    catch (const SolverControl::NoConvergence &e)
      {
        throw_no_convergence(e,
                             (use_region_solver ?
                                region_solver.target_of_last_solve() :
                                control.tolerance()),
                             tolerance,
                             max_iterations);
      }
    return 0;
  }



  template <int dim>
  double
  DamageSystem<dim>::solve_work() const
  {
    return work_of_solves;
  }



  template <int dim>
  bool
  DamageSystem<dim>::solves_on_free_nodes() const
  {
    return use_region_solver && !use_snes_vi;
  }



  template <int dim>
  unsigned int
  DamageSystem<dim>::solve_free(const LA::MPI::Vector           &b,
                                LA::MPI::Vector                 &x,
                                const std::vector<unsigned int> &free,
                                const double                     tolerance,
                                const unsigned int               max_iterations)
  {
    Assert(solves_on_free_nodes(), ExcInternalError());
    try
      {
        const unsigned int iterations
          = region_solver.solve_free(b, x, free, tolerance, max_iterations);
        work_of_solves += double(free.size()) * iterations;
        return iterations;
      }
    catch (const SolverControl::NoConvergence &e)
      {
        throw_no_convergence(e,
                             region_solver.target_of_last_solve(),
                             tolerance,
                             max_iterations);
      }
    return 0;
  }



  template <int dim>
  void
  DamageSystem<dim>::throw_no_convergence(const SolverControl::NoConvergence &e,
                                          const double       target,
                                          const double       tolerance,
                                          const unsigned int max_iterations)
  {
    // Every rank gets here in the same iteration (the residual is global).
    AssertThrow(false,
                ExcMessage("CG did not converge for the damage: after "
                           + std::to_string(e.last_step)
                           + " iterations the residual is "
                           + to_text(e.last_residual) + " > " + to_text(target)
                           + " (" + to_text(tolerance)
                           + " times |b| on the free nodes). Raise "
                             "Solver/Maximum linear iterations = "
                           + std::to_string(max_iterations)
                           + "; a looser Solver/Relative tolerance helps only "
                             "the solves that stop at it (the first solves "
                             "of a step stop at 1e-4 or at it, if looser)."));
  }



  template class DamageSystem<2>;
  template class DamageSystem<3>;
} // namespace VPContact
