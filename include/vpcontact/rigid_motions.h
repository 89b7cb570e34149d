// Whether the boundary conditions hold the body: a displacement problem whose
// constraints leave a rigid motion free has no unique solution, and solvers
// return displacements of any size for it.
#ifndef vpcontact_rigid_motions_h
#define vpcontact_rigid_motions_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Throw a message if some rigid motion of the body (a translation or a
   * rotation, or a combination) satisfies every constraint of
   * @p constraints on the displacement components 0..dim-1 of
   * @p dof_handler: clamped, roller and prescribed boundaries, bilateral
   * contact and stick nodes hold the body, hanging nodes do not. The motion
   * r is free if r_i = sum_j a_ij r_j on every constrained line
   * i = sum_j a_ij j + b; the check is the smallest eigenvalue of the Gram
   * matrix of these residuals over all ranks. @p remedy ends the message.
   * Collective.
   */
  template <int dim>
  void
  check_rigid_motions_held(const DoFHandler<dim>           &dof_handler,
                           const AffineConstraints<double> &constraints,
                           const std::string               &remedy);
} // namespace VPContact

#endif
