// The simulator's assembly: the elastic stiffness matrix (once per mesh) and
// the load vector (once per step).
#include <vpcontact/simulator.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::assemble_stiffness_matrix()
  {
    TimerOutput::Scope t(computing_timer, "Assemble matrix");

    // K_ij = (E eps(phi_j), eps(phi_i)). The constraints are homogeneous, so
    // the matrix is the same for every load and is assembled once.
    const QGauss<dim>                quadrature(fe.degree + 1);
    FEValues<dim>                    fe_values(fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    const unsigned int               dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double>               cell_matrix(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    std::vector<SymmetricTensor<2, dim>> eps_phi(dofs_per_cell);
    const SymmetricTensor<4, dim>       &E = material.stiffness();

    stiffness_matrix = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_matrix = 0.;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                eps_phi[i] = fe_values[u].symmetric_gradient(i, q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const SymmetricTensor<2, dim> E_eps_i = E * eps_phi[i];
                  for (unsigned int j = 0; j <= i; ++j)
                    cell_matrix(i, j)
                      += (E_eps_i * eps_phi[j]) * fe_values.JxW(q);
                }
            }
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);

          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(cell_matrix,
                                                 dof_indices,
                                                 stiffness_matrix);
        }
    stiffness_matrix.compress(VectorOperation::add);
  }



  template <int dim>
  void
  Simulator<dim>::assemble_load_vector(const double time)
  {
    TimerOutput::Scope t(computing_timer, "Assemble load");

    // b_i = (f_B(t), phi_i) + (f_N(t), phi_i)_{Gamma_N}.
    boundary_conditions.set_time(time);
    const QGauss<dim>     quadrature(fe.degree + 1);
    const QGauss<dim - 1> face_quadrature(fe.degree + 1);
    const bool        with_body_force = boundary_conditions.has_body_force();
    FEValues<dim>     fe_values(fe,
                            quadrature,
                            update_values | update_quadrature_points
                              | update_JxW_values);
    FEFaceValues<dim> fe_face_values(fe,
                                     face_quadrature,
                                     update_values | update_quadrature_points
                                       | update_JxW_values);
    const FEValuesExtractors::Vector     u(0);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>                       cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> dof_indices(dofs_per_cell);
    Vector<double>                       load(dim);
    Tensor<1, dim>                       load_tensor;

    load_vector = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_rhs      = 0.;
          bool has_load = false;
          if (with_body_force)
            {
              has_load = true;
              fe_values.reinit(cell);
              for (const unsigned int q : fe_values.quadrature_point_indices())
                {
                  boundary_conditions.body_force()
                    .vector_value(fe_values.quadrature_point(q), load);
                  for (unsigned int d = 0; d < dim; ++d)
                    load_tensor[d] = load[d];
                  for (unsigned int i = 0; i < dofs_per_cell; ++i)
                    cell_rhs(i) += load_tensor * fe_values[u].value(i, q)
                                   * fe_values.JxW(q);
                }
            }
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary()
                && boundary_conditions.is_traction_boundary(
                  face->boundary_id()))
              {
                has_load = true;
                fe_face_values.reinit(cell, face);
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  {
                    boundary_conditions.traction()
                      .vector_value(fe_face_values.quadrature_point(q), load);
                    for (unsigned int d = 0; d < dim; ++d)
                      load_tensor[d] = load[d];
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      cell_rhs(i) += load_tensor * fe_face_values[u].value(i, q)
                                     * fe_face_values.JxW(q);
                  }
              }
          if (has_load)
            {
              cell->get_dof_indices(dof_indices);
              constraints.distribute_local_to_global(cell_rhs,
                                                     dof_indices,
                                                     load_vector);
            }
        }
    load_vector.compress(VectorOperation::add);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
