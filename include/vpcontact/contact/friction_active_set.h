// The contact and separation, stick and slip sets of the contact nodes for
// Tresca or Coulomb friction with bilateral or unilateral contact, and what
// they do to the linear system: contact nodes hold their normal displacement,
// stick nodes are constrained, slip nodes carry a known friction force.
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
   * With unilateral contact (TrescaFriction::unilateral()) the normal
   * displacement is not constrained by the boundary conditions but by this
   * set: a node in contact holds u_i.nu_i = g_0,i (a constraint on its
   * component d with the largest |nu_d|), a separated node is free and
   * carries no friction. Its tangent space is the plane normal to nu_i,
   * within the components the boundary conditions leave free. The normal
   * multiplier p_i = r_i.nu_i / m_i is the contact pressure -sigma_nu and
   * d_i = g_0,i - u_i.nu_i the gap; the semismooth Newton step for
   * p_i >= 0, d_i >= 0, p_i d_i = 0 puts a node in contact where
   * p_i - c d_i > 0 (Hueber, Stadler and Wohlmuth). A node that comes into
   * contact starts in the stick set; at t = 0 the nodes with g_0 = 0 are in
   * contact. With Coulomb's law the bound of each node is
   * g_i = mu_i max(p_i, 0) from the last solve: the iteration has converged
   * when, besides the sets, no bound moves by more than the bound
   * tolerance.
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
      /// Nodes that entered or left the stick set or the contact set (the
      /// constraints change).
      unsigned int n_stick_changed = 0;
      /// Nodes whose slip stiffness changed (the matrix changes): the stick
      /// changes, and the direction changes where the tangent space is a
      /// plane.
      unsigned int n_matrix_changed = 0;
      /// Nodes whose Coulomb bound moved by more than the tolerance.
      unsigned int n_bounds_moved = 0;
      /// If the sets after this update are those after an earlier update
      /// of the step although they changed since: how many updates ago
      /// (0: no cycle). Set by FrictionProblem::update().
      unsigned int cycle_length = 0;
    };

    /**
     * Find the contact nodes from @p base_constraints (Dirichlet and, for
     * bilateral contact, normal constraints, closed) and compute their
     * lumped lengths and normals. All nodes start in the stick set;
     * with unilateral contact, those with an initial gap g_0(x_i, 0) > 0
     * start separated.
     */
    void
    setup(const DoFHandler<dim>              &dof_handler,
          const AffineConstraints<double>    &base_constraints,
          const std::set<types::boundary_id> &contact_ids,
          const IndexSet                     &locally_relevant_dofs,
          const TrescaFriction<dim>          &law);

    /// At the start of a step at @p time: the Tresca bounds
    /// g_i = g(x_i, t) (Coulomb keeps those of the last iterate) and the
    /// initial gaps g_0(x_i, t).
    void
    set_bounds(const TrescaFriction<dim> &friction, const double time);

    /**
     * Unilateral contact: u.nu = g_0 at every node in contact, as a
     * constraint on the increment from the ghosted displacement
     * @p previous of the last step (nullptr: zero), before the stick
     * constraints and constraints.close().
     */
    void
    add_contact_constraints(AffineConstraints<double> &constraints,
                            const LA::MPI::Vector     *previous) const;

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
     * Recompute p, lambda and w from the ghosted @p residual, @p increment
     * and last step's displacement @p previous, and take the next sets:
     * contact or separation (unilateral), then stick or slip with
     * tresca_decision(), using c of complementarity_constant(). A slip
     * node keeps its direction and slip stiffness while its direction
     * moves by at most the direction tolerance of @p law. Coulomb's bounds
     * follow the pressures of this iterate.
     */
    Changes
    update(const LA::MPI::Vector     &residual,
           const LA::MPI::Vector     &increment,
           const LA::MPI::Vector     &previous,
           const double               youngs_modulus,
           const TrescaFriction<dim> &law);

    /// Global numbers of stick and slip nodes.
    std::pair<unsigned int, unsigned int>
    count() const;

    /// Put the slip node with the smallest |lambda + c w| - g of the last
    /// update() (the lowest global dof among equals) into the stick set, on
    /// every rank that sees it; false if no node slips.
    bool
    keep_one_stick();

    /// A fingerprint of the contact, stick and slip sets of all ranks (the
    /// same on every rank): equal sets give equal fingerprints.
    unsigned long long
    fingerprint() const;

    /// What a step of unilateral contact reports (all ranks).
    struct NormalMeasures
    {
      unsigned int n_contact   = 0;
      unsigned int n_separated = 0;
      /// The lumped measure of Gamma_C at nodes in contact and at stick
      /// nodes: lengths in 2D, areas in 3D.
      double contact_measure = 0;
      double stick_measure   = 0;
      double max_pressure    = 0;
      /// sum_i m_i p_i over the nodes in contact: the normal force the
      /// foundation carries (per unit thickness in 2D), and
      /// |sum_i m_i lambda_i|, the size of the net friction force.
      double normal_force     = 0;
      double tangential_force = 0;
      /// max of (-p)^+ at contact nodes and |p| at separated ones, relative
      /// to the stress scale of max_violation().
      double pressure_violation = 0;
      /// max of |d| at contact nodes and (-d)^+ at separated ones [m].
      double gap_violation = 0;
    };

    NormalMeasures
    normal_measures() const;

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

    /// The contact pressure p_i into the x component and the gap d_i into
    /// the y component of the owned contact nodes of @p normal (zeroed
    /// first).
    void
    fill_normal_output(LA::MPI::Vector &normal) const;

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
    /// node this rank sees. Throws if a value is not a status, unless
    /// @p interpolated (a state carried to a new mesh): then such a node
    /// sticks, and a slip direction of another length is normalized.
    void
    read_state(const LA::MPI::Vector &state, const bool interpolated = false);

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
      /// The unit normal nu_i, the component d it constrains in contact
      /// (unilateral), the initial gap, the pressure p_i, the gap d_i, the
      /// friction coefficient mu_i (Coulomb).
      Tensor<1, dim> normal;
      unsigned int   normal_component = 0;
      double         initial_gap      = 0;
      double         pressure         = 0;
      double         gap              = 0;
      double         mu               = 0;
      /// |lambda + c w| - g of the last decision: how far from sticking.
      double        excess = 0;
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

    /// With unilateral contact: the tangent space of @p node from its
    /// normal, within what @p base_constraints leave free; false if they
    /// hold its normal component.
    bool
    make_unilateral_node(const AffineConstraints<double> &base_constraints,
                         Node                            &node) const;

    /// p, d, lambda, w and |r|/m of every node from the ghosted residual,
    /// increment and last step's displacement; returns the largest
    /// Coulomb bound mu max(p, 0) of all ranks.
    double
    measure(const LA::MPI::Vector &residual,
            const LA::MPI::Vector &increment,
            const LA::MPI::Vector &previous);

    /// The next normal state of @p node from its p and d (unilateral):
    /// whether it changed between contact and separation.
    bool
    decide_contact(Node &node, const double c) const;

    /// The bound of @p node for this iterate: g (Tresca) or mu max(p, 0)
    /// (Coulomb); whether it moved by more than the tolerance of @p law
    /// relative to @p scale.
    bool
    update_bound(Node                      &node,
                 const TrescaFriction<dim> &law,
                 const double               scale) const;

    std::vector<Node> nodes;
    MPI_Comm          communicator = MPI_COMM_WORLD;
    bool              unilateral   = false;
    bool              coulomb      = false;
  };
} // namespace VPContact

#endif
