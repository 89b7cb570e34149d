// The owned damage nodes that a damage solve of the step can change: the
// damage step's passes between its CG solves visit these, not the mesh.
#ifndef vpcontact_damage_work_set_h
#define vpcontact_damage_work_set_h

#include <vpcontact/damage/support_product.h>

#include <vector>

namespace VPContact
{
  /**
   * Between two CG solves the primal-dual active set of the damage bounds
   * forms the right-hand side, adds the bound changes, takes the residual
   * and decides the sets again. Done over all nodes, that is about a dozen
   * passes over the mesh per solve, while the damage moves only at the
   * free nodes and at the nodes put on a bound they were not on: the
   * "moving" nodes. Everywhere else a node sits on its bound with change
   * zero; if its neighbours do too, its residual is the step's b - K
   * zeta_{n-1} and its damage zeta_{n-1}, the data of the step's first
   * decision, and box_decision() on the same data keeps the set it gave.
   *
   * This class holds the owned positions that may differ from that: the
   * moving nodes, their neighbours in the matrix graph, the hanging nodes
   * with theirs, and on several ranks the rows coupled to ghosts (whose
   * values come from the other ranks). It is built once a step, after the
   * step's first decision, where fewer than a quarter of the nodes move, and
   * grows as nodes change set; the passes of
   * DamageProblem::solve_on_work_set() visit its positions only, in
   * ascending order, so their sums are those of the passes over all nodes
   * to the bit.
   */
  class DamageWorkSet
  {
  public:
    /// No positions, out of @p n_owned.
    void
    clear(const unsigned int n_owned);

    /// Add the owned @p positions.
    void
    add(const std::vector<unsigned int> &positions);

    /// Add the owned @p positions and their neighbours (the rows of their
    /// columns in @p product's matrix).
    void
    add_neighbourhoods(const std::vector<unsigned int> &positions,
                       const SupportProduct            &product);

    /// The positions, ascending.
    const std::vector<unsigned int> &
    positions() const;

  private:
    /// Mark @p position as a member, to be merged.
    void
    insert(const unsigned int position)
    {
      if (!member[position])
        {
          member[position] = true;
          added.push_back(position);
        }
    }

    /// Merge the positions added since the last call into the list.
    void
    merge_added();

    std::vector<bool>         member;
    std::vector<unsigned int> list;
    std::vector<unsigned int> added;
  };
} // namespace VPContact

#endif
