// Whether the boundary conditions hold the body: a displacement problem whose
// constraints leave a rigid motion of some part of the mesh free has no
// unique solution, and solvers return displacements of any size for it.
#ifndef vpcontact_rigid_motions_h
#define vpcontact_rigid_motions_h

#include <vpcontact/fe/mesh_parts.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Which rigid motions (translations, rotations, or combinations) of each
   * connected part of the mesh (MeshParts) satisfy every constraint on the
   * displacement components 0..dim-1 of a DoFHandler: clamped, roller and
   * prescribed boundaries, bilateral contact and stick nodes hold a part,
   * hanging nodes do not. The motion r of a part is free if
   * r_i = sum_j a_ij r_j on every constrained line i = sum_j a_ij j + b
   * (r vanishing off the part); the test is the smallest eigenvalue of the
   * Gram matrix of these residuals over all ranks. Built once per mesh,
   * asked for any number of constraint sets. Collective.
   */
  template <int dim>
  class RigidMotionCheck
  {
  public:
    explicit RigidMotionCheck(const DoFHandler<dim> &dof_handler);

    /**
     * For every part that @p constraints do not hold, its number and the
     * motion it is free to make ("a translation in x", ...). Empty if
     * every part is held.
     */
    std::vector<std::pair<unsigned int, std::string>>
    free_motions(const AffineConstraints<double> &constraints) const;

    /**
     * Throw a message if free_motions() is not empty: the motion and, on a
     * mesh of several parts, the part (its cells, bounding box and boundary
     * ids). @p remedy ends the message.
     */
    void
    assert_held(const AffineConstraints<double> &constraints,
                const std::string               &remedy) const;

    const MeshParts<dim> &
    parts() const;

  private:
    /// Component and position of a displacement dof, relative to the
    /// centre of its part and scaled by the part's size, by dof.
    using Nodes
      = std::map<types::global_dof_index, std::pair<unsigned int, Point<dim>>>;

    /// The nodes of the owned lines of @p constraints and of the dofs they
    /// refer to, where this rank sees them.
    Nodes
    constrained_nodes(const AffineConstraints<double> &constraints) const;

    /// The Gram matrices of all parts, part after part, row by row.
    std::vector<double>
    gram_matrices(const AffineConstraints<double> &constraints) const;

    const DoFHandler<dim> &dof_handler;
    MeshParts<dim>         mesh_parts;
  };
} // namespace VPContact

#endif
