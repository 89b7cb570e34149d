// Lumped measures of the contact boundary at its vertices: lengths (areas)
// and outward normals, for the contact nodes' multipliers and normals.
#include <vpcontact/contact/boundary_measures.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

namespace VPContact
{
  // The lumped length m_i = int_{Gamma_C} phi_i ds of every contact
  // vertex, at its x-component dof, as a ghosted vector.
  template <int dim>
  LA::MPI::Vector
  lumped_lengths(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &contact_ids,
                 const IndexSet                     &locally_relevant_dofs)
  {
    const auto     &fe           = dof_handler.get_fe();
    const IndexSet &owned_dofs   = dof_handler.locally_owned_dofs();
    const MPI_Comm  communicator = dof_handler.get_communicator();
    const auto      on_contact   = [&](const auto &face) {
      return face->at_boundary() && contact_ids.count(face->boundary_id()) == 1;
    };
    // The lumped length m_i = int_{Gamma_C} phi_i ds (trapezoidal rule on
    // each face), accumulated at the x-component dof of each vertex. The
    // vector can write into ghost entries, which compress() sends to their
    // owners.
    LA::MPI::Vector lengths;
    lengths.reinit(owned_dofs, locally_relevant_dofs, communicator, true);
    const Quadrature<dim - 1> face_quadrature
      = fe.reference_cell()
          .face_reference_cell(0)
          .template get_gauss_type_quadrature<dim - 1>(2);
    FEFaceValues<dim> fe_face_values(get_default_linear_mapping(
                                       dof_handler.get_triangulation()),
                                     fe,
                                     face_quadrature,
                                     update_values | update_JxW_values);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (on_contact(face))
            {
              fe_face_values.reinit(cell, face);
              cell->get_dof_indices(dof_indices);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (fe.system_to_component_index(i).first == 0)
                  {
                    double integral = 0;
                    for (const unsigned int q :
                         fe_face_values.quadrature_point_indices())
                      integral += fe_face_values.shape_value(i, q)
                                  * fe_face_values.JxW(q);
                    if (integral != 0.)
                      lengths(dof_indices[i]) += integral;
                  }
            }
    lengths.compress(VectorOperation::add);
    LA::MPI::Vector relevant_lengths(owned_dofs,
                                     locally_relevant_dofs,
                                     communicator);
    relevant_lengths = lengths;
    return relevant_lengths;
  }



  template <int dim>
  LA::MPI::Vector
  lumped_normals(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &contact_ids,
                 const IndexSet                     &locally_relevant_dofs)
  {
    // As lumped_lengths(), with each component d of the face's normal at
    // the d-component dof of the vertex.
    const auto     &fe           = dof_handler.get_fe();
    const MPI_Comm  communicator = dof_handler.get_communicator();
    LA::MPI::Vector normals;
    normals.reinit(dof_handler.locally_owned_dofs(),
                   locally_relevant_dofs,
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
                  const unsigned int d = fe.system_to_component_index(i).first;
                  if (d >= dim)
                    continue;
                  double integral = 0;
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    integral += fe_face_values.shape_value(i, q)
                                * fe_face_values.normal_vector(q)[d]
                                * fe_face_values.JxW(q);
                  if (integral != 0.)
                    normals(dof_indices[i]) += integral;
                }
            }
    normals.compress(VectorOperation::add);
    LA::MPI::Vector relevant(dof_handler.locally_owned_dofs(),
                             locally_relevant_dofs,
                             communicator);
    relevant = normals;
    return relevant;
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
