// Measures of the contact boundary at its vertices, as ghosted vectors on
// the displacement dofs: the lumped length (area) m_i of Gamma_C at each
// vertex and the body's lumped outward normal there.
#ifndef vpcontact_boundary_measures_h
#define vpcontact_boundary_measures_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>

#include <set>

namespace VPContact
{
  using namespace dealii;

  /// m_i = int_{Gamma_C} phi_i ds at the x-component dof of every vertex of
  /// the faces with @p contact_ids (trapezoidal rule), ghosted.
  template <int dim>
  LA::MPI::Vector
  lumped_lengths(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &contact_ids,
                 const IndexSet                     &locally_relevant_dofs);

  /**
   * int_{Gamma_C} phi_i n_d ds at the d-component dof of every vertex of
   * the faces with @p contact_ids, ghosted: at a vertex, the sum of its
   * faces' outward normals weighted by their measure, the same on every
   * rank that sees the vertex. Normalised, the vertex's normal.
   */
  template <int dim>
  LA::MPI::Vector
  lumped_normals(const DoFHandler<dim>              &dof_handler,
                 const std::set<types::boundary_id> &contact_ids,
                 const IndexSet                     &locally_relevant_dofs);
} // namespace VPContact

#endif
