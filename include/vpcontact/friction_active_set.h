// The stick and slip sets of the contact nodes for Tresca friction, and what
// they do to the linear system: stick nodes are constrained, slip nodes carry
// a known friction force.
#ifndef vpcontact_friction_active_set_h
#define vpcontact_friction_active_set_h

#include <vpcontact/tresca_friction.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <set>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The primal-dual active set of the contact nodes (as step-41/42's
   * active set, for Tresca friction in 2D).
   *
   * A contact node is a vertex of Gamma_C whose normal displacement is
   * constrained by the bilateral condition and whose tangential
   * displacement is free (a vertex also on a Dirichlet part is not a contact
   * node: the clamp wins). Its tangent t_i is read off the normal constraint
   * u_a = c u_f, so that the free degree of freedom u_f moves the node along
   * t_i. Friction is evaluated with nodal quadrature: m_i is the lumped
   * length of Gamma_C at the node, lambda_i = t_i . r_i / m_i the friction
   * multiplier from the residual r = b - A(du) (lambda = -sigma_tau) and
   * w_i = t_i . du_i the tangential increment (k times the slip velocity).
   *
   * Decisions are taken for every locally relevant node from ghosted
   * vectors, so that a node on a processor boundary is decided alike on
   * every rank that sees it; changes are counted on owned nodes and summed.
   */
  template <int dim>
  class FrictionActiveSet
  {
  public:
    struct Changes
    {
      /// Nodes that changed set or slip direction (all ranks).
      unsigned int n_changed = 0;
      /// Nodes that entered or left the stick set (the matrix changes).
      unsigned int n_stick_changed = 0;
    };

    /**
     * Find the contact nodes from @p base_constraints (Dirichlet and normal
     * constraints, closed) and compute their lumped lengths. All nodes start
     * in the stick set.
     */
    void
    setup(const DoFHandler<dim>              &dof_handler,
          const AffineConstraints<double>    &base_constraints,
          const std::set<types::boundary_id> &contact_ids,
          const IndexSet                     &locally_relevant_dofs);

    /// g_i = g(x_i, t) at every node.
    void
    set_bounds(const TrescaFriction<dim> &friction, const double time);

    /// Add u_f = 0 for every stick node (before constraints.close()).
    void
    add_stick_constraints(AffineConstraints<double> &constraints) const;

    /// Add the friction force -m_i g_i s_i t_i of every owned slip node.
    void
    add_slip_forces(const AffineConstraints<double> &constraints,
                    TrilinosWrappers::MPI::Vector   &rhs) const;

    /**
     * Recompute lambda and w from the ghosted @p residual and @p increment
     * and take the next sets with tresca_decision(), using
     * c = @p c_factor * @p youngs_modulus / m_i.
     */
    Changes
    update(const TrilinosWrappers::MPI::Vector &residual,
           const TrilinosWrappers::MPI::Vector &increment,
           const double                         youngs_modulus,
           const double                         c_factor);

    /// Global numbers of stick and slip nodes.
    std::pair<unsigned int, unsigned int>
    count() const;

    /// max_i |lambda_i| / g_i over nodes with g_i > 0 (all ranks).
    double
    max_utilisation() const;

    /**
     * The largest violation of the discrete Tresca conditions, relative to
     * g: max over nodes of (|lambda_i| - g_i)^+ and, where |w_i| > 0, of
     * |lambda_i - g_i sign(w_i)|. Zero up to the solver tolerance when the
     * iteration has converged.
     */
    double
    max_violation(const double slip_tolerance) const;

    /**
     * Write the status (0 none, 1 stick, 2 slip) into the x component and
     * the tangential traction sigma_tau = -lambda into the y component of
     * the owned contact nodes of @p output (a vector on all dofs).
     */
    void
    fill_output(TrilinosWrappers::MPI::Vector &output) const;

    bool
    empty() const;

    /// The degrees of freedom of the contact nodes this rank sees (of a
    /// DoFHandler with @p n_dofs of them).
    IndexSet
    node_dofs(const types::global_dof_index n_dofs) const;

    /**
     * For checkpoints: write the set of every owned contact node into
     * @p state (a vector on all dofs): its status (1 stick, 2 slip) into
     * the x component and its slip direction (-1, 0, 1) into the y
     * component. Stored as a finite element vector, the sets travel with
     * the mesh to any number of ranks.
     */
    void
    write_state(TrilinosWrappers::MPI::Vector &state) const;

    /// The inverse of write_state(), from a ghosted @p state, for every
    /// node this rank sees. Throws if a value is not a status.
    void
    read_state(const TrilinosWrappers::MPI::Vector &state);

  private:
    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      types::global_dof_index                  free_dof;
      Tensor<1, dim>                           tangent;
      Point<dim>                               position;
      bool                                     owned     = false;
      double                                   length    = 0;
      double                                   g         = 0;
      double                                   lambda    = 0;
      double                                   slip      = 0;
      ContactStatus                            status    = ContactStatus::stick;
      double                                   direction = 0;
    };

    std::vector<Node> nodes;
    MPI_Comm          communicator = MPI_COMM_WORLD;
  };
} // namespace VPContact

#endif
