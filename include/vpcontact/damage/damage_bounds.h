// The bounds 0 <= zeta <= 1 of the damage, enforced exactly by a primal-dual
// active set on the nodal values (step-41's obstacle method, two-sided).
#ifndef vpcontact_damage_bounds_h
#define vpcontact_damage_bounds_h

#include <vpcontact/damage/support_product.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>

#include <utility>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /// Where a nodal damage value is: at a bound, or free between them.
  enum class BoundStatus
  {
    lower = -1, // zeta = 0, fully damaged
    free  = 0,
    upper = 1 // zeta = 1, sound
  };

  /**
   * The primal-dual active set decision for one node of the box [0, 1].
   * With lambda = (b - K zeta)_i the residual (the multiplier: lambda > 0
   * pushes up against 1, lambda < 0 down against 0) and c > 0, the
   * conditions 0 <= zeta <= 1, lambda (zeta - 1) = 0 where lambda > 0,
   * lambda zeta = 0 where lambda < 0 are equivalent to
   *   lambda = max(0, lambda + c (zeta - 1)) + min(0, lambda + c zeta),
   * whose semismooth Newton step is: upper where lambda + c (zeta - 1) > 0,
   * lower where lambda + c zeta < 0, free elsewhere.
   *
   * A node whose multiplier is zero at the bound (weakly active) would flip
   * between two sets on round-off alone; with @p tolerance > 0 a node
   * leaves its @p current set only if the test is violated by more than
   * @p tolerance (in units of lambda), which ends such cycles.
   */
  inline BoundStatus
  box_decision(const double      lambda,
               const double      zeta,
               const double      c,
               const BoundStatus current   = BoundStatus::free,
               const double      tolerance = 0.)
  {
    // Entering a set needs the test to hold by more than the tolerance;
    // staying in it, only not to fail by more than the tolerance. Inline:
    // DamageBounds::update() calls it for every node after every damage
    // solve.
    const double upper_margin
      = (current == BoundStatus::upper ? -tolerance : tolerance);
    const double lower_margin
      = (current == BoundStatus::lower ? -tolerance : tolerance);
    if (lambda + c * (zeta - 1.) > upper_margin)
      return BoundStatus::upper;
    if (lambda + c * zeta < -lower_margin)
      return BoundStatus::lower;
    return BoundStatus::free;
  }

  /**
   * The active sets of the damage bounds on the locally relevant damage
   * degrees of freedom. Decisions are taken on every relevant node from
   * ghosted vectors (the same on every rank that sees it); changes are
   * counted on owned nodes and summed over the ranks.
   */
  class DamageBounds
  {
  public:
    /**
     * @p damage_dofs are the locally relevant damage degrees of freedom
     * that carry bounds (indices into the vectors passed to the other
     * functions), @p lumped_mass a ghosted vector of the lumped masses m_i.
     * All nodes start free.
     */
    void
    setup(const IndexSet        &damage_dofs,
          const IndexSet        &locally_owned_dofs,
          const LA::MPI::Vector &lumped_mass,
          const MPI_Comm         communicator);

    /**
     * The owned nodes of the active sets with the change of the damage that
     * puts them on their bound: their positions among the owned entries
     * are appended to @p held, and @p change gets 1 - zeta_old at those of
     * the upper set and -zeta_old at those of the lower one (its other
     * entries are left alone), zeta_old read from @p old_damage. Both
     * vectors hold the owned entries.
     */
    void
    held_changes(const LA::MPI::Vector     &old_damage,
                 std::vector<unsigned int> &held,
                 LA::MPI::Vector           &change) const;

    /**
     * held_changes() for the owned positions @p work alone (ascending; see
     * DamageWorkSet): @p change gets the change that puts a node of an
     * active set on its bound and 0 at the other positions of @p work; the
     * positions of the free nodes go to @p free, the others (the active
     * sets and positions without bounds, the hanging nodes) to @p held.
     */
    void
    held_changes_on(const std::vector<unsigned int> &work,
                    const LA::MPI::Vector           &old_damage,
                    LA::MPI::Vector                 &change,
                    std::vector<unsigned int>       &held,
                    std::vector<unsigned int>       &free) const;

    /**
     * The owned positions of the nodes whose change is not zero in a solve
     * with the present sets: the free nodes, and the nodes of an active
     * set whose old value @p old_damage (owned) is not on the bound.
     */
    std::vector<unsigned int>
    moving_positions(const LA::MPI::Vector &old_damage) const;

    /**
     * The scale c_i of the complementarity test of update(): the ghosted
     * @p diagonal of the damage matrix, K_ii = m_i/k + kappa A_ii (laid out
     * like the lumped mass). Without it, update() takes c_i = m_i/k, which
     * is too small beside kappa A_ii where kappa k / h^2 is large: the sets
     * then trade nodes between iterations instead of settling.
     */
    void
    set_complementarity_scale(const LA::MPI::Vector &diagonal);

    /**
     * The next sets from the ghosted @p residual and @p damage (laid out
     * like the lumped mass given to setup()), with the scale c_i of
     * set_complementarity_scale() (or m_i / k, the diagonal of M/k) and the
     * hysteresis tolerance 1e-9 c (a change of the damage of 1e-9, far
     * below anything the model resolves). Returns the number of nodes that
     * changed set, on all ranks.
     */
    unsigned int
    update(const LA::MPI::Vector &residual,
           const LA::MPI::Vector &damage,
           const double           time_step);

    /**
     * update() on the owned nodes at the positions @p work (see
     * DamageWorkSet) and on every ghost node. The other owned nodes keep
     * their set: the caller guarantees that their residual and damage are
     * those of an earlier update() in the same step, whose decision
     * box_decision() repeats. The owned positions of the nodes that changed
     * set go to @p changed.
     */
    unsigned int
    update_on(const std::vector<unsigned int> &work,
              const LA::MPI::Vector           &residual,
              const LA::MPI::Vector           &damage,
              const double                     time_step,
              std::vector<unsigned int>       &changed);

    /**
     * The motion of the front of the upper set (ζ = 1) over a step, in
     * rings of nodes. begin_step() records the upper set and the number of
     * its nodes on the front (those with a neighbour below 1: an entry of
     * the damage matrix K, which @p product multiplies, in the numbering
     * of the bounds);
     * rings_moved() returns the number of nodes that have left the upper
     * set since, divided by that front size.
     */
    void
    begin_step(SupportProduct &product);

    double
    rings_moved() const;

    /**
     * Free the nodes of the upper set within @p rings rings of the nodes
     * below 1. Returns the number of nodes freed, on all ranks.
     *
     * Why: a node leaves the upper set only once its multiplier turns
     * negative, which needs a free neighbour, so every semismooth Newton
     * iteration moves the front by one ring, and a step moves it by more
     * rings the finer the mesh. Freed ahead of time, by as many rings as the
     * front moved in the previous step, the nodes that should stay at 1 come
     * out above 1 in the next solve and go back in one iteration (a local
     * test); the sets found at the end are the exact ones, confirmed by an
     * exact solve as always.
     */
    unsigned int
    free_ahead_of_front(SupportProduct &product, const unsigned int rings);

    /// The sets of all nodes, to go back to with restore_sets().
    const std::vector<BoundStatus> &
    sets() const;

    /// Go back to the sets @p saved of sets(), taken after begin_step().
    void
    restore_sets(const std::vector<BoundStatus> &saved);

    /// Global sizes of the lower and upper sets.
    std::pair<unsigned int, unsigned int>
    count() const;

    /// For checkpoints: write the set of every owned node (-1 lower, 0
    /// free, 1 upper) into its entry of @p state (a vector on all dofs).
    void
    write_state(LA::MPI::Vector &state) const;

    /// The inverse of write_state(), from a ghosted @p state, for every
    /// relevant node. Throws if a value is not a set, unless
    /// @p interpolated (a state carried to a new mesh): then such a node
    /// is free.
    void
    read_state(const LA::MPI::Vector &state, const bool interpolated = false);

  private:
    /// The set of node @p i from the ghosted @p residual and @p damage
    /// values; true if it changed.
    bool
    decide(const unsigned int i,
           const double      *residual_values,
           const double      *damage_values,
           const double       time_step);

    /// Check that @p residual and @p damage are laid out as setup() says.
    void
    check_layout(const LA::MPI::Vector &residual,
                 const LA::MPI::Vector &damage) const;

    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  mass;
    /// c_i of set_complementarity_scale() (empty: m_i / k).
    std::vector<double> scale;
    std::vector<bool>   owned;
    /// Positions of the nodes in the local storage of a ghosted vector laid
    /// out like the lumped mass (n_ghosted entries), and among the owned
    /// entries (owned nodes only).
    std::vector<unsigned int> ghosted_position;
    std::vector<unsigned int> owned_position;
    /// The node at each owned position (-1: no bounds, a hanging node), and
    /// the nodes that are not owned.
    std::vector<int>          node_of_owned;
    std::vector<unsigned int> ghost_nodes;
    int                       n_ghosted = 0;
    std::vector<BoundStatus>  status;
    std::vector<bool>         upper_at_start;
    unsigned int              front_size = 0;

    /// The owned upper nodes with a neighbour below 1 (see
    /// front_by_product() and front_by_graph()).
    std::vector<unsigned int>
    front(SupportProduct &product);

    /// front() on several ranks: one matrix-vector product with K.
    std::vector<unsigned int>
    front_by_product(SupportProduct &product) const;

    /// front() on one rank, from the graph of K (@p rows): the nodes near
    /// the last front and near the nodes that changed set since.
    std::vector<unsigned int>
    front_by_graph(const OwnedRows &rows);

    /// The nodes that can be on the front now, ascending: those near the
    /// last front and near the nodes that changed set since.
    std::vector<unsigned int>
    front_candidates(const OwnedRows &rows);

    /// What front_by_graph() found last: the front, the upper set (one
    /// byte per node) and the rows it read (nullptr: none yet on this
    /// mesh).
    std::vector<unsigned int> last_front;
    std::vector<char>         upper_at_last_front;
    const OwnedRows          *rows_of_last_front = nullptr;

    /// On one rank: the upper nodes next to the nodes of @p ring, which
    /// are free, in the graph of @p rows; they are freed too.
    std::vector<unsigned int>
    free_next_ring(const std::vector<unsigned int> &ring,
                   const OwnedRows                 &rows);

    /// Pass each neighbour j of node @p i in the graph of @p rows (one rank:
    /// an entry K_ij that is not zero, at a node with bounds, i itself left
    /// out) to @p visit, until it returns true.
    template <typename Visit>
    void
    for_each_neighbour(const unsigned int i,
                       const OwnedRows   &rows,
                       const Visit       &visit) const;

    /// The marks of front_by_product() and their product with the matrix,
    /// kept.
    mutable LA::MPI::Vector front_marks;
    mutable LA::MPI::Vector front_reach;
    MPI_Comm                communicator = MPI_COMM_WORLD;
  };
} // namespace VPContact

#endif
