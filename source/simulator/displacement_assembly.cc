// The displacement problem's assembly: the elastic stiffness matrix (once per
// mesh) and the right-hand side of a step, which carries the stress history.
#include <vpcontact/fe/cell_translation.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/simulator/displacement_problem.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parallel.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>
#include <string>

namespace VPContact
{
  namespace
  {
    // The element matrix (E eps(phi_j), eps(phi_i)) of the cell that
    // @p fe_values was last reinitialized on, for its displacement shape
    // functions @p shape. Each of them is primitive (one nonzero vector
    // component a, with gradient g): eps(phi_i) is the symmetric part of
    // e_a (x) g_i, and with the symmetries of E
    //
    //   (E eps(phi_j)) : eps(phi_i) = sum_{c,d} E_{a c b d} g_i[c] g_j[d]
    //
    // for the components a of phi_i and b of phi_j, as step-8 writes it for
    // the isotropic law. Per point, the sums over c for each phi_i come
    // first (the row W_i[b][d], dim^3 products), then each entry is a dot
    // product of dim terms; building the symmetric gradients and
    // contracting them with E entry by entry costs about twice the
    // products and most of the time of a 3D matrix assembly, which a
    // change of the stick set repeats.
    template <int dim>
    void
    elastic_cell_matrix(const FEValues<dim>             &fe_values,
                        const std::vector<unsigned int> &shape,
                        const SymmetricTensor<4, dim>   &E,
                        FullMatrix<double>              &cell_matrix)
    {
      const FiniteElement<dim> &fe = fe_values.get_fe();
      const unsigned int        n  = shape.size();
      std::vector<unsigned int> component(n);
      for (unsigned int i = 0; i < n; ++i)
        component[i] = fe.system_to_component_index(shape[i]).first;
      // E's entries in a plain array: SymmetricTensor's accessors look up
      // the stored entry of each index quadruple.
      double stiffness[dim][dim][dim][dim];
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int d = 0; d < dim; ++d)
              stiffness[a][c][b][d] = E[a][c][b][d];
      std::vector<Tensor<1, dim>> gradient(n);
      std::vector<Tensor<2, dim>> weighted_row(n);
      cell_matrix.reinit(n, n);
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double JxW = fe_values.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            {
              gradient[i]          = fe_values.shape_grad(shape[i], q);
              const unsigned int a = component[i];
              Tensor<2, dim>    &W = weighted_row[i];
              for (unsigned int b = 0; b < dim; ++b)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    double sum = 0.;
                    for (unsigned int c = 0; c < dim; ++c)
                      sum += stiffness[a][c][b][d] * gradient[i][c];
                    W[b][d] = sum * JxW;
                  }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j <= i; ++j)
              cell_matrix(i, j) += weighted_row[i][component[j]] * gradient[j];
        }
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 1; j < n; ++j)
          cell_matrix(i, j) = cell_matrix(j, i);
    }



    // Add the matrix of a cell none of whose degrees of freedom is
    // constrained and all of whose rows this rank owns (nearly every cell)
    // to @p matrix, and return true; return false, having added nothing,
    // for any other cell. The same values go to the same entries, cell by
    // cell in the same order, as distribute_local_to_global() adds them,
    // but into Epetra's local rows and columns directly: that path sorts
    // the cell's indices, looks up their constraints, and converts the
    // column of every entry to Epetra's local numbering (576 lookups for a
    // 3D cell, against 48 here): a large part of the time of an assembly,
    // which each change of the stick set repeats.
    bool
    add_plain_cell_matrix(
      const FullMatrix<double>                   &cell_matrix,
      const std::vector<types::global_dof_index> &dof_indices,
      const AffineConstraints<double>            &constraints,
      const IndexSet                             &owned,
      LA::SparseMatrix                           &matrix,
      std::vector<int>                           &local_rows,
      std::vector<int>                           &local_columns)
    {
      for (const auto dof : dof_indices)
        if (!owned.is_element(dof) || constraints.is_constrained(dof))
          return false;
      // deal.II gives only const access to the Epetra matrix; its values
      // change here, its structure does not.
      auto &epetra = const_cast<Epetra_CrsMatrix &>(matrix.trilinos_matrix());
      const unsigned int n = dof_indices.size();
      local_rows.resize(n);
      local_columns.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const int dof    = static_cast<int>(dof_indices[i]);
          local_rows[i]    = epetra.RowMap().LID(dof);
          local_columns[i] = epetra.ColMap().LID(dof);
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          const int error = epetra.SumIntoMyValues(local_rows[i],
                                                   n,
                                                   &cell_matrix(i, 0),
                                                   local_columns.data());
          AssertThrow(error == 0,
                      ExcMessage("Epetra could not add a cell's matrix (error "
                                 + std::to_string(error)
                                 + "): the sparsity pattern lacks a coupling "
                                   "of the cell's degrees of freedom."));
        }
      return true;
    }



    // Add what a cell computed for the right-hand side (a
    // DisplacementProblem::CellRhs) to @p rhs: a plain cell's entries straight
    // to the local storage, at the position of each degree of freedom in the
    // rank's contiguous range starting at @p first_owned (what
    // distribute_local_to_global() does for them, without its lookups of
    // the constraints and of Trilinos' local index); the other cells'
    // through @p constraints, with the lift of an inhomogeneous one.
    template <typename CellRhs>
    void
    add_to_rhs(const CellRhs                   &copy,
               const AffineConstraints<double> &constraints,
               const types::global_dof_index    first_owned,
               LA::MPI::Vector                 &rhs)
    {
      if (copy.plain)
        {
          double *const entries = rhs.begin();
          for (unsigned int i = 0; i < copy.dof_indices.size(); ++i)
            entries[copy.dof_indices[i] - first_owned] += copy.cell_rhs(i);
        }
      else if (copy.inhomogeneous)
        constraints.distribute_local_to_global(copy.cell_rhs,
                                               copy.dof_indices,
                                               rhs,
                                               copy.cell_matrix);
      else
        constraints.distribute_local_to_global(copy.cell_rhs,
                                               copy.dof_indices,
                                               rhs);
    }
  } // namespace



  template <int dim>
  void
  DisplacementProblem<dim>::assemble_stiffness_matrix()
  {
    TimerOutput::Scope t(computing_timer, "Assemble matrix");
    // A factorization begun in the background reads the matrix.
    displacement.solver.wait_for_factors();

    // K_ij = (E eps(phi_j), eps(phi_i)): the paper's matrix k E divided by
    // k, since the unknown is the increment k w. It does not change while
    // the mesh is fixed, except where friction changes it: the stick nodes'
    // constraints and, in 3D, the slip nodes' stiffness.
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    FullMatrix<double>                   cell_matrix;
    std::vector<types::global_dof_index> dof_indices;
    std::vector<int>                     local_rows, local_columns;

    // The mapping is linear and the material the same in every cell, so a
    // cell that is the last computed one moved (is_translate()) has its
    // matrix: on a subdivided box one matrix serves every cell of the
    // rank, where computing them was most of an assembly, which every
    // change of the stick set repeats. The cells come in the same order
    // in a run resumed from a checkpoint, which so computes the same bits.
    const cell_iterator *reference = nullptr;
    displacement.matrix            = 0.;
    for (const auto &cell : owned_cells)
      {
        if (reference == nullptr || !is_translate(cell, *reference))
          {
            fe_values.reinit(cell);
            elastic_cell_matrix(fe_values,
                                displacement.shape_functions,
                                material.stiffness(),
                                cell_matrix);
            reference = &cell;
          }
        get_displacement_dof_indices(cell, dof_indices);
        if (!add_plain_cell_matrix(cell_matrix,
                                   dof_indices,
                                   constraints,
                                   displacement.owned,
                                   displacement.matrix,
                                   local_rows,
                                   local_columns))
          constraints.distribute_local_to_global(cell_matrix,
                                                 dof_indices,
                                                 displacement.matrix);
      }
    if (friction_problem)
      friction_problem->add_slip_stiffness(constraints, displacement.matrix);
    displacement.matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::add_cell_loads(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const FEValues<dim>                                  &fe_values,
    FEFaceValues<dim>                                    &fe_face_values,
    Vector<double>                                       &cell_vector) const
  {
    // (f_B(t), phi_i) + (f_N(t), phi_i)_{Gamma_N}, at the time last given to
    // boundary_conditions.set_time(); fe_values must be reinitialized on
    // cell if there is a body force (the traction uses fe_face_values).
    // add_load() adds (f, phi_i) at the points of its FEValues, for the
    // body force on the cell and the traction on a face alike; it runs (and
    // allocates its load vector) only where there is a load, since this
    // runs on every cell of every step and most cells have none.
    const auto add_load = [&](const Function<dim>     &load_function,
                              const FEValuesBase<dim> &values) {
      const FEValuesExtractors::Vector u(0);
      Vector<double>                   load(dim);
      Tensor<1, dim>                   load_tensor;
      for (const unsigned int q : values.quadrature_point_indices())
        {
          load_function.vector_value(values.quadrature_point(q), load);
          for (unsigned int d = 0; d < dim; ++d)
            load_tensor[d] = load[d];
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            cell_vector(i)
              += load_tensor * values[u].value(i, q) * values.JxW(q);
        }
    };
    if (boundary_conditions.has_body_force())
      add_load(boundary_conditions.body_force(), fe_values);
    for (const auto &face : cell->face_iterators())
      if (face->at_boundary()
          && boundary_conditions.is_traction_boundary(face->boundary_id()))
        {
          fe_face_values.reinit(cell, face);
          add_load(boundary_conditions.traction(face->boundary_id()),
                   fe_face_values);
        }
  }



  template <int dim>
  void
  DisplacementProblem<dim>::assemble_rhs(const double time,
                                         const bool   with_viscoplastic_rate,
                                         const bool   predictor_stored)
  {
    TimerOutput::Scope t(computing_timer, "Assemble right-hand side");

    // b_i = (f_B(t_n), phi_i) + (f_N(t_n), phi_i)_{Gamma_N}
    //       - (sigma_{n-1} + k G_{n-1}, eps(phi_i)).
    // The predictor sigma_{n-1} + k G_{n-1} is stored at each quadrature
    // point for the stress update; G is evaluated only for a law that is
    // not zero, with the state of step n-1 (forward Euler).
    boundary_conditions.set_time(time);
    const double k = time_discretization.step_size();
    const bool   evaluate_rate
      = with_viscoplastic_rate && !viscoplastic_law->is_zero();
    const bool          body_force = boundary_conditions.has_body_force();
    const double *const solution_entries
      = cell_kinematics.local_entries(solution);

    // The plain cells (no constrained entry, all owned) in the threads
    // deal.II has, color by color (see ConflictFreeChunks): each adds its
    // vector to the owned entries by position, and every entry is the same
    // sum with any number of threads. Then, in this thread, the other
    // cells through the constraints.
    const IndexSet &owned = displacement.owned;
    AssertThrow(owned.is_contiguous()
                  && displacement.rhs.trilinos_vector().Map().LinearMap(),
                ExcInternalError());
    const types::global_dof_index first_owned
      = (owned.n_elements() > 0 ? *owned.begin() : 0);
    if (rhs_chunks.outdated(owned_cells.size(), constraints))
      rhs_chunks.reinit(
        owned_cells.size(),
        [this](const std::size_t i, auto &indices) {
          get_displacement_dof_indices(owned_cells[i], indices);
        },
        first_owned,
        owned.n_elements(),
        constraints,
        std::max<std::size_t>(64,
                              owned_cells.size()
                                / (32 * MultithreadInfo::n_threads())));
    displacement.rhs = 0.;
    for (unsigned int color = 0; color < rhs_chunks.colors().size(); ++color)
      add_plain_cells(color,
                      time - k,
                      evaluate_rate,
                      predictor_stored,
                      body_force,
                      solution_entries);
    add_other_cells(time - k,
                    evaluate_rate,
                    predictor_stored,
                    body_force,
                    solution_entries);
    displacement.rhs.compress(VectorOperation::add);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::add_plain_cells(
    const unsigned int  color,
    const double        previous_time,
    const bool          evaluate_rate,
    const bool          predictor_stored,
    const bool          body_force,
    const double *const solution_entries)
  {
    // The chunks of one color add to no common entry: they run in any
    // threads at once. A plain cell has no constraint, so only its loads
    // need its FEValues (a body force, or a traction face).
    const std::vector<unsigned int> &chunks  = rhs_chunks.colors()[color];
    double *const                    entries = displacement.rhs.begin();
    const auto                      &shape   = displacement.shape_functions;
    parallel::apply_to_subranges(
      std::size_t(0),
      chunks.size(),
      [&](const std::size_t begin, const std::size_t end) {
        AssemblyScratch scratch(mapping,
                                fe,
                                quadrature,
                                discretization.face_quadrature());
        for (std::size_t c = begin; c < end; ++c)
          for (const std::size_t i : rhs_chunks.plain_cells(chunks[c]))
            {
              const auto &cell = owned_cells[i];
              compute_cell_rhs(cell,
                               previous_time,
                               evaluate_rate,
                               predictor_stored,
                               solution_entries,
                               scratch);
              if (body_force)
                scratch.fe_values.reinit(cell);
              if (body_force || cell->at_boundary())
                add_cell_loads(cell,
                               scratch.fe_values,
                               scratch.fe_face_values,
                               scratch.cell_vector);
              const unsigned int *const position = rhs_chunks.positions(i);
              for (unsigned int a = 0; a < shape.size(); ++a)
                entries[position[a]] += scratch.cell_vector(shape[a]);
            }
      },
      1);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::add_other_cells(
    const double        previous_time,
    const bool          evaluate_rate,
    const bool          predictor_stored,
    const bool          body_force,
    const double *const solution_entries)
  {
    // The cells with a constrained or a ghost entry, one after the other:
    // their vectors go through the constraints.
    const IndexSet               &owned = displacement.owned;
    const types::global_dof_index first_owned
      = (owned.n_elements() > 0 ? *owned.begin() : 0);
    AssemblyScratch scratch(mapping,
                            fe,
                            quadrature,
                            discretization.face_quadrature());
    CellRhs         copy(displacement.shape_functions.size());
    for (const std::size_t i : rhs_chunks.other_cells())
      {
        compute_cell_rhs(owned_cells[i],
                         previous_time,
                         evaluate_rate,
                         predictor_stored,
                         solution_entries,
                         scratch);
        get_displacement_dof_indices(owned_cells[i], copy.dof_indices);
        add_cell_loads_and_lifts(owned_cells[i], body_force, scratch, copy);
        add_to_rhs(copy, constraints, first_owned, displacement.rhs);
      }
  }



  template <int dim>
  void
  DisplacementProblem<dim>::subtract_predictor_work(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    AssemblyScratch                                      &scratch) const
  {
    // -(sigma_{n-1} + k G_{n-1}, eps(phi_i)) from the predictor stored at
    // the points (by this pass, or by an earlier pass of this step).
    const auto history = stress_history.get_data(cell);
    const auto JxW     = stress_history.JxW(cell);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      scratch.weighted_predictor[q] = history[q].predictor * JxW[q];
    cell_kinematics.subtract_stress_work(cell,
                                         make_array_view(std::as_const(
                                           scratch.weighted_predictor)),
                                         scratch.cell_vector);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::compute_cell_rhs(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const double                                          previous_time,
    const bool                                            evaluate_rate,
    const bool                                            predictor_stored,
    const double *const                                   solution_entries,
    AssemblyScratch                                      &scratch)
  {
    // The strains, the damage and the work of the predictor come from
    // CellKinematics; an FEValues is reinitialized only on the cells that
    // carry a load or an inhomogeneous constraint, in add_cell_rhs(): about
    // half the time of an FEValues on every cell, the same printed results.
    // A stored predictor is the same number a new pass would give (its
    // data, of step n-1, do not change within the step), and the stress at
    // the points may already be that of step n (see update_stress_ahead()).
    const bool   with_damage = damage_model.is_active() && !predictor_stored;
    const double k           = time_discretization.step_size();
    scratch.cell_vector.reinit(fe.n_dofs_per_cell());
    if (predictor_stored)
      {
        subtract_predictor_work(cell, scratch);
        return;
      }
    if (evaluate_rate || with_damage)
      cell_kinematics.strains(cell,
                              solution_entries,
                              make_array_view(scratch.strains));
    if (with_damage)
      cell_kinematics.damage(cell,
                             solution_entries,
                             make_array_view(scratch.damage_values));
    if (with_damage
        && scratch.damage_source_thread != std::this_thread::get_id())
      {
        scratch.damage_source        = &damage_model.source();
        scratch.damage_source_thread = std::this_thread::get_id();
      }
    const auto history = stress_history.get_data(cell);
    const auto sources = stress_history.damage_sources(cell);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        auto &point     = history[q];
        point.predictor = point.stress;
        if (evaluate_rate)
          point.predictor += k
                             * viscoplastic_law->rate(point.stress,
                                                      scratch.strains[q],
                                                      scratch.damage_values[q]);
        if (with_damage)
          sources[q]
            = scratch.damage_source->value(scratch.strains[q],
                                           point.stress,
                                           scratch.damage_values[q],
                                           cell_kinematics.point(cell, q),
                                           previous_time);
      }
    subtract_predictor_work(cell, scratch);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::add_cell_loads_and_lifts(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const bool                                            body_force,
    AssemblyScratch                                      &scratch,
    CellRhs                                              &copy)
  {
    // The loads, and the matrix that lifts an inhomogeneous constraint,
    // need the FEValues of the cell: only cells with a body force, a
    // traction face or such a constraint reinitialize it. Only a
    // constrained degree of freedom can be inhomogeneously so.
    copy.inhomogeneous = false;
    copy.plain         = true;
    for (const auto dof : copy.dof_indices)
      if (constraints.is_constrained(dof))
        {
          copy.plain = false;
          copy.inhomogeneous |= constraints.is_inhomogeneously_constrained(dof);
        }
      else if (!displacement.owned.is_element(dof))
        copy.plain = false;
    if (body_force || copy.inhomogeneous)
      scratch.fe_values.reinit(cell);
    if (body_force || cell->at_boundary())
      add_cell_loads(cell,
                     scratch.fe_values,
                     scratch.fe_face_values,
                     scratch.cell_vector);
    if (copy.inhomogeneous)
      elastic_cell_matrix(scratch.fe_values,
                          displacement.shape_functions,
                          material.stiffness(),
                          copy.cell_matrix);
    for (unsigned int i = 0; i < displacement.shape_functions.size(); ++i)
      copy.cell_rhs(i) = scratch.cell_vector(displacement.shape_functions[i]);
  }



  template <int dim>
  void
  DisplacementProblem<dim>::assemble_residual(
    const std::vector<typename DoFHandler<dim>::active_cell_iterator> &cells,
    LA::MPI::Vector &residual) const
  {
    TimerOutput::Scope t(computing_timer, "Assemble residual");

    // r_i = (f_B, phi_i) + (f_N, phi_i)_{Gamma_N} - (sigma, eps(phi_i)) with
    // the stress sigma = sigma_{n-1} + k G_{n-1} + E eps(du) of the current
    // increment, without condensing the constraints: at a contact node its
    // tangential part is the friction force (lambda_i m_i), its normal part
    // the reaction of the foundation. Loads are at the time of the last
    // assemble_rhs(). Only those entries are read, so only @p cells, those
    // with a contact node, are visited: the other entries of r are
    // incomplete. The caller compresses @p residual.
    AssemblyScratch                  scratch(mapping,
                            fe,
                            quadrature,
                            discretization.face_quadrature());
    FEValues<dim>                   &fe_values      = scratch.fe_values;
    FEFaceValues<dim>               &fe_face_values = scratch.fe_face_values;
    const FEValuesExtractors::Vector u(0);
    const unsigned int               dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>                   cell_residual(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::vector<SymmetricTensor<2, dim>> strain_increments(quadrature.size());

    for (const auto &cell : cells)
      {
        cell_residual = 0.;
        fe_values.reinit(cell);
        fe_values[u].get_function_symmetric_gradients(increment,
                                                      strain_increments);
        const auto history = stress_history.get_data(cell);
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const SymmetricTensor<2, dim> stress
              = history[q].predictor + material.stress(strain_increments[q]);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              cell_residual(i) -= stress * fe_values[u].symmetric_gradient(i, q)
                                  * fe_values.JxW(q);
          }
        add_cell_loads(cell, fe_values, fe_face_values, cell_residual);
        cell->get_dof_indices(dof_indices);
        residual.add(dof_indices, cell_residual);
      }
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
