// Lumped measures of the contact boundary at its vertices: lengths (areas)
// and outward normals, for the contact nodes' multipliers and normals.
#include <vpcontact/contact/boundary_measures.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <functional>

namespace VPContact
{
  namespace
  {
    // int_{Gamma_C} phi_i w_d(n) ds at every dof i of component d of the
    // vertices of the faces with @p contact_ids (trapezoidal rule on each
    // face, w_d(n) = @p weight(d, n) with n the face's outward normal), as a
    // ghosted vector. The vector accumulates into ghost entries, which
    // compress() sends to their owners.
    template <int dim>
    LA::MPI::Vector
    lumped_integrals(
      const DoFHandler<dim>              &dof_handler,
      const std::set<types::boundary_id> &contact_ids,
      const IndexSet                     &relevant,
      const std::function<double(unsigned int, const Tensor<1, dim> &)> &weight)
    {
      const auto     &fe           = dof_handler.get_fe();
      const MPI_Comm  communicator = dof_handler.get_communicator();
      LA::MPI::Vector sums;
      sums.reinit(dof_handler.locally_owned_dofs(),
                  relevant,
                  communicator,
                  true);
      const Quadrature<dim - 1> face_quadrature
        = fe.reference_cell()
            .face_reference_cell(0)
            .template get_gauss_type_quadrature<dim - 1>(2);
      FEFaceValues<dim> fe_face_values(
        get_default_linear_mapping(dof_handler.get_triangulation()),
        fe,
        face_quadrature,
        update_values | update_JxW_values | update_normal_vectors);
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && contact_ids.count(face->boundary_id()))
              {
                fe_face_values.reinit(cell, face);
                cell->get_dof_indices(dof_indices);
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  {
                    const unsigned int d
                      = fe.system_to_component_index(i).first;
                    double integral = 0;
                    for (const unsigned int q :
                         fe_face_values.quadrature_point_indices())
                      integral += fe_face_values.shape_value(i, q)
                                  * weight(d, fe_face_values.normal_vector(q))
                                  * fe_face_values.JxW(q);
                    if (integral != 0.)
                      sums(dof_indices[i]) += integral;
                  }
              }
      sums.compress(VectorOperation::add);
      LA::MPI::Vector ghosted(dof_handler.locally_owned_dofs(),
                              relevant,
                              communicator);
      ghosted = sums;
      return ghosted;
    }
  } // namespace



  template <int dim>
  LA::MPI::Vector
  lumped_lengths(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &contact_ids,
                 const IndexSet                     &locally_relevant_dofs)
  {
    // m_i at the x-component dof of each vertex.
    return lumped_integrals<dim>(dof_handler,
                                 contact_ids,
                                 locally_relevant_dofs,
                                 [](const unsigned int d,
                                    const Tensor<1, dim> &) {
                                   return d == 0 ? 1. : 0.;
                                 });
  }



  template <int dim>
  LA::MPI::Vector
  lumped_normals(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &contact_ids,
                 const IndexSet                     &locally_relevant_dofs)
  {
    // Each component d of the faces' normal at the d-component dof.
    return lumped_integrals<dim>(dof_handler,
                                 contact_ids,
                                 locally_relevant_dofs,
                                 [](const unsigned int    d,
                                    const Tensor<1, dim> &n) {
                                   return d < dim ? n[d] : 0.;
                                 });
  }



  template LA::MPI::Vector
  lumped_lengths(const DoFHandler<2> &,
                 const std::set<types::boundary_id> &,
                 const IndexSet &);
  template LA::MPI::Vector
  lumped_lengths(const DoFHandler<3> &,
                 const std::set<types::boundary_id> &,
                 const IndexSet &);
  template LA::MPI::Vector
  lumped_normals(const DoFHandler<2> &,
                 const std::set<types::boundary_id> &,
                 const IndexSet &);
  template LA::MPI::Vector
  lumped_normals(const DoFHandler<3> &,
                 const std::set<types::boundary_id> &,
                 const IndexSet &);
} // namespace VPContact
