// The stick and slip sets of the contact nodes for Tresca friction, and what
// they do to the linear system: stick nodes are constrained, slip nodes carry
// a known friction force.
#ifndef vpcontact_friction_active_set_h
#define vpcontact_friction_active_set_h

#include <vpcontact/contact/tresca_friction.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <set>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The primal-dual active set of the contact nodes (as step-41/42's
   * active set), for Tresca friction on contact lines (2D) and surfaces
   * (3D).
   *
   * A contact node is a vertex of Gamma_C whose normal displacement is
   * constrained by the bilateral condition and which has at least one free
   * displacement component (a vertex also on a Dirichlet part is not a
   * contact node: the clamp wins). Its tangent space is read off the
   * constraints: moving a free degree of freedom u_f by 1 moves the node by
   * e_f + sum_a c_af e_a, where u_a = sum_f c_af u_f are its constrained
   * components. The space is a line in 2D, a plane on a 3D surface, and a
   * line again on an edge where the contact surface meets a roller;
   * P_i is the projection onto it. Friction is evaluated with nodal
   * quadrature: m_i is the lumped measure of Gamma_C at the node,
   * lambda_i = P_i r_i / m_i the friction multiplier from the residual
   * r = b - A(du) (lambda = -sigma_tau) and w_i = P_i du_i the tangential
   * increment (k times the slip velocity).
   *
   * A stick node holds its free components (w_i = 0). A slip node carries
   * the linearised slip law of tresca_decision(): the force
   * -m_i g_i n_i and the stiffness m_i beta_i (P_i - n_i n_i^T), which is
   * zero on a line. Each iteration is a semismooth Newton step for the
   * ball |lambda_i| <= g_i; it has converged when no node changes set and
   * no slip direction moves by more than the direction tolerance.
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
      /// Nodes that entered or left the stick set (the constraints change).
      unsigned int n_stick_changed = 0;
      /// Nodes whose slip stiffness changed (the matrix changes): the stick
      /// changes, and the direction changes where the tangent space is a
      /// plane.
      unsigned int n_matrix_changed = 0;
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

    /// Add the friction force -m_i g_i n_i of every owned slip node.
    void
    add_slip_forces(const AffineConstraints<double> &constraints,
                    LA::MPI::Vector                 &rhs) const;

    /// Add the slip stiffness m_i beta_i (P_i - n_i n_i^T) of every owned
    /// slip node whose tangent space is a plane (before compress()).
    void
    add_slip_stiffness(const AffineConstraints<double> &constraints,
                       LA::SparseMatrix                &matrix);

    /**
     * After an update() that turned slip directions but changed no set:
     * add to @p matrix, which holds the slip stiffness of the last
     * add_slip_stiffness() or update_slip_stiffness(), the change of every
     * owned node's slip stiffness, and compress it.
     */
    void
    update_slip_stiffness(const AffineConstraints<double> &constraints,
                          LA::SparseMatrix                &matrix);

    /**
     * Recompute lambda and w from the ghosted @p residual and @p increment
     * and take the next sets with tresca_decision(), using
     * c = @p c_factor * @p youngs_modulus / m_i. A slip node keeps its
     * direction and slip stiffness while its direction moves by at most
     * @p direction_tolerance.
     */
    Changes
    update(const LA::MPI::Vector &residual,
           const LA::MPI::Vector &increment,
           const double           youngs_modulus,
           const double           c_factor,
           const double           direction_tolerance);

    /// Global numbers of stick and slip nodes.
    std::pair<unsigned int, unsigned int>
    count() const;

    /// max_i g_i (all ranks).
    double
    max_bound() const;

    /// max_i |lambda_i| / g_i over nodes with g_i > 0, 1 at slip nodes (all
    /// ranks).
    double
    max_utilisation() const;

    /**
     * The largest violation of the discrete Tresca conditions: max over
     * nodes of (|lambda_i| - g_i)^+ and, where |w_i| exceeds
     * @p slip_tolerance times the largest |w|, of |lambda_i - g_i w_i/|w_i||,
     * relative to the stress scale max_i max(g_i, |r_i| / m_i) (the bound or
     * the whole contact traction, normal part included, whichever is
     * larger). Zero up to the solver tolerance when the iteration has
     * converged, also as g tends to 0.
     */
    double
    max_violation(const double slip_tolerance) const;

    /**
     * Zero both vectors, then write the status (0 none, 1 stick, 2 slip)
     * into the x component of
     * the owned contact nodes of @p status and the tangential traction
     * sigma_tau = -lambda into their displacement components of
     * @p traction (vectors on all dofs); in 2D its component along the
     * node's tangent into the x component.
     */
    void
    fill_output(LA::MPI::Vector &status, LA::MPI::Vector &traction) const;

    bool
    empty() const;

    /// The degrees of freedom of the contact nodes this rank sees (of a
    /// DoFHandler with @p n_dofs of them).
    IndexSet
    node_dofs(const types::global_dof_index n_dofs) const;

    /**
     * For checkpoints: write the set of every owned contact node into
     * @p state (a vector on all dofs): its status (1 stick, 2 slip) into
     * the x component and the coordinates of its slip direction in its
     * tangent basis into the next ones (in 2D -1, 0 or 1). Stored as a
     * finite element vector, the sets travel with the mesh to any number of
     * ranks. A resumed slip node's first iteration has no slip stiffness:
     * its direction is a fixed point until it next changes.
     */
    void
    write_state(LA::MPI::Vector &state) const;

    /// The inverse of write_state(), from a ghosted @p state, for every
    /// node this rank sees. Throws if a value is not a status.
    void
    read_state(const LA::MPI::Vector &state);

  private:
    /// Tangential vectors in the coordinates of a node's tangent basis
    /// (dim - 1 of them; on a tangent line the second is 0).
    using TangentVector = Tensor<1, dim - 1>;

    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      std::vector<types::global_dof_index>     free_dofs;
      /// An orthonormal basis of the tangent space (1 or dim - 1 vectors).
      std::vector<Tensor<1, dim>> tangents;
      Point<dim>                  position;
      bool                        owned  = false;
      double                      length = 0;
      double                      g      = 0;
      TangentVector               lambda;
      /// |r_i| / m_i: the whole contact traction, normal part included.
      double        traction = 0;
      TangentVector slip;
      ContactStatus status = ContactStatus::stick;
      TangentVector direction;
      double        slip_stiffness = 0;
      /// The direction and slip stiffness the matrix holds.
      TangentVector assembled_direction;
      double        assembled_stiffness = 0;

      /// m beta (P - n n^T) of the direction @p n (coordinates) and
      /// @p beta, in the node's displacement components.
      FullMatrix<double>
      slip_stiffness_matrix(const TangentVector &n, const double beta) const;

      /// The coordinates of the tangential part of @p v.
      TangentVector
      coordinates(const Tensor<1, dim> &v) const;

      /// The vector of the coordinates @p c.
      Tensor<1, dim>
      vector(const TangentVector &c) const;
    };

    /// The node of the vertex @p v of @p face, if it is a contact node.
    bool
    make_node(const typename DoFHandler<dim>::face_iterator &face,
              const unsigned int                             v,
              const AffineConstraints<double>               &base_constraints,
              Node                                          &node) const;

    std::vector<Node> nodes;
    MPI_Comm          communicator = MPI_COMM_WORLD;
  };
} // namespace VPContact

#endif
