// The primal-dual active set for the damage bounds [0, 1].
#include <vpcontact/damage/damage_bounds.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <algorithm>

namespace VPContact
{
  void
  DamageBounds::setup(const IndexSet        &damage_dofs,
                      const IndexSet        &locally_owned_dofs,
                      const LA::MPI::Vector &lumped_mass,
                      const MPI_Comm         mpi_communicator)
  {
    // Where each node sits in the local storage of a ghosted vector laid
    // out like @p lumped_mass, and of an owned one: update() and
    // held_changes() run after every damage solve over all nodes, and a
    // Trilinos vector read by global index costs a hash lookup per entry.
    communicator = mpi_communicator;
    dofs.clear();
    mass.clear();
    scale.clear();
    owned.clear();
    ghosted_position.clear();
    owned_position.clear();
    node_of_owned.assign(locally_owned_dofs.n_elements(), -1);
    ghost_nodes.clear();
    const Epetra_BlockMap &ghosted_map = lumped_mass.trilinos_vector().Map();
    n_ghosted                          = ghosted_map.NumMyElements();
    // Sized as they end: they are kept for the mesh.
    const std::size_t n_nodes = damage_dofs.n_elements();
    for (auto *list : {&ghosted_position, &owned_position})
      list->reserve(n_nodes);
    dofs.reserve(n_nodes);
    mass.reserve(n_nodes);
    owned.reserve(n_nodes);
    for (const auto dof : damage_dofs)
      {
        dofs.push_back(dof);
        mass.push_back(lumped_mass(dof));
        owned.push_back(locally_owned_dofs.is_element(dof));
        ghosted_position.push_back(
          ghosted_map.LID(static_cast<TrilinosWrappers::types::int_type>(dof)));
        owned_position.push_back(
          owned.back() ? locally_owned_dofs.index_within_set(dof) : 0);
        if (owned.back())
          node_of_owned[owned_position.back()] = dofs.size() - 1;
        else
          ghost_nodes.push_back(dofs.size() - 1);
      }
    status.assign(dofs.size(), BoundStatus::free);
    upper_at_start.assign(dofs.size(), false);
    front_size = 0;
    last_front.clear();
    upper_at_last_front.clear();
    rows_of_last_front = nullptr;
  }



  void
  DamageBounds::held_changes(const LA::MPI::Vector     &old_damage,
                             std::vector<unsigned int> &held,
                             LA::MPI::Vector           &change) const
  {
    const double *old_values    = old_damage.begin();
    double       *change_values = change.begin();
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (owned[i] && status[i] != BoundStatus::free)
        {
          const unsigned int position = owned_position[i];
          held.push_back(position);
          change_values[position] = (status[i] == BoundStatus::upper ? 1. : 0.)
                                    - old_values[position];
        }
  }



  void
  DamageBounds::set_complementarity_scale(const LA::MPI::Vector &diagonal)
  {
    scale.resize(dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      scale[i] = diagonal(dofs[i]);
  }



  void
  DamageBounds::held_changes_on(const std::vector<unsigned int> &work,
                                const LA::MPI::Vector           &old_damage,
                                LA::MPI::Vector                 &change,
                                std::vector<unsigned int>       &held,
                                std::vector<unsigned int>       &free) const
  {
    const double *old_values    = old_damage.begin();
    double       *change_values = change.begin();
    for (const unsigned int position : work)
      {
        const int i             = node_of_owned[position];
        change_values[position] = 0.;
        if (i >= 0 && status[i] == BoundStatus::free)
          free.push_back(position);
        else
          {
            held.push_back(position);
            if (i >= 0)
              change_values[position]
                = (status[i] == BoundStatus::upper ? 1. : 0.)
                  - old_values[position];
          }
      }
  }



  std::vector<unsigned int>
  DamageBounds::moving_positions(const LA::MPI::Vector &old_damage) const
  {
    const double             *old_values = old_damage.begin();
    std::vector<unsigned int> moving;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (owned[i])
        {
          const double old = old_values[owned_position[i]];
          if (status[i] == BoundStatus::free
              || (status[i] == BoundStatus::upper && old != 1.)
              || (status[i] == BoundStatus::lower && old != 0.))
            moving.push_back(owned_position[i]);
        }
    return moving;
  }



  void
  DamageBounds::check_layout(const LA::MPI::Vector &residual,
                             const LA::MPI::Vector &damage) const
  {
    AssertThrow(residual.trilinos_vector().Map().NumMyElements() == n_ghosted
                  && damage.trilinos_vector().Map().NumMyElements()
                       == n_ghosted,
                ExcInternalError("DamageBounds::update() needs ghosted "
                                 "vectors laid out like the lumped mass."));
  }



  bool
  DamageBounds::decide(const unsigned int i,
                       const double      *residual_values,
                       const double      *damage_values,
                       const double       time_step)
  {
    // Weakly active nodes: a hysteresis of 1e-9 in units of zeta.
    constexpr double   hysteresis = 1e-9;
    const double       c = (scale.empty() ? mass[i] / time_step : scale[i]);
    const unsigned int position = ghosted_position[i];
    const BoundStatus  next     = box_decision(residual_values[position],
                                          damage_values[position],
                                          c,
                                          status[i],
                                          hysteresis * c);
    const bool         changed  = (next != status[i]);
    status[i]                   = next;
    return changed;
  }



  unsigned int
  DamageBounds::update(const LA::MPI::Vector &residual,
                       const LA::MPI::Vector &damage,
                       const double           time_step)
  {
    check_layout(residual, damage);
    unsigned int n_changed = 0;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      n_changed
        += (decide(i, residual.begin(), damage.begin(), time_step) && owned[i]);
    return Utilities::MPI::sum(n_changed, communicator);
  }



  unsigned int
  DamageBounds::update_on(const std::vector<unsigned int> &work,
                          const LA::MPI::Vector           &residual,
                          const LA::MPI::Vector           &damage,
                          const double                     time_step,
                          std::vector<unsigned int>       &changed)
  {
    check_layout(residual, damage);
    changed.clear();
    for (const unsigned int position : work)
      if (const int i = node_of_owned[position];
          i >= 0 && decide(i, residual.begin(), damage.begin(), time_step))
        changed.push_back(position);
    for (const unsigned int i : ghost_nodes)
      decide(i, residual.begin(), damage.begin(), time_step);
    return Utilities::MPI::sum(static_cast<unsigned int>(changed.size()),
                               communicator);
  }



  std::vector<unsigned int>
  DamageBounds::front(SupportProduct &product)
  {
    return (Utilities::MPI::n_mpi_processes(communicator) == 1 ?
              front_by_graph(product.rows()) :
              front_by_product(product));
  }



  std::vector<unsigned int>
  DamageBounds::front_by_product(SupportProduct &product) const
  {
    // With marks m = 1 on the nodes below 1, (K m)_i sums the entries K_ij
    // of the marked neighbours j of node i. Where kappa A is an M-matrix
    // (Q1 cells of aspect ratio up to about 1.4) these are negative, so the
    // sum is nonzero exactly on the neighbours; elsewhere a neighbour may
    // be missed, which costs only the iteration this was to save. The
    // product also reaches across ranks. The two vectors are kept (fresh ones
    // cost their page faults at every call, two or more per step) and are read
    // and written by position.
    const IndexSet &owned_rows = product.rows().halo()->locally_owned_range();
    if (front_marks.size() != owned_rows.size()
        || front_marks.locally_owned_elements() != owned_rows)
      {
        front_marks.reinit(owned_rows, communicator);
        front_reach.reinit(owned_rows, communicator);
      }
    front_marks         = 0.;
    double *const marks = front_marks.begin();
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (owned[i] && status[i] != BoundStatus::upper)
        marks[owned_position[i]] = 1.;
    product.vmult(front_reach, front_marks);
    const double *const       reach = front_reach.begin();
    std::vector<unsigned int> on_front;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (owned[i] && status[i] == BoundStatus::upper
          && reach[owned_position[i]] != 0.)
        on_front.push_back(i);
    return on_front;
  }



  template <typename Visit>
  void
  DamageBounds::for_each_neighbour(const unsigned int i,
                                   const OwnedRows   &rows,
                                   const Visit       &visit) const
  {
    // Rows of constrained (hanging) nodes carry no bounds, and are nobody's
    // neighbour here, as their marks are zero in the product.
    const unsigned int  row     = owned_position[i];
    const unsigned int *columns = rows.columns().data();
    const double       *values  = rows.values().data();
    for (unsigned int e = rows.row_start()[row]; e < rows.row_start()[row + 1];
         ++e)
      {
        const int j
          = (columns[e] < node_of_owned.size() ? node_of_owned[columns[e]] :
                                                 -1);
        if (j >= 0 && static_cast<unsigned int>(j) != i && values[e] != 0.
            && visit(static_cast<unsigned int>(j)))
          return;
      }
  }



  std::vector<unsigned int>
  DamageBounds::front_by_graph(const OwnedRows &rows)
  {
    // On one rank every neighbour is a node of this rank, and the front is
    // found from the graph of K alone. On an M-matrix the same nodes as
    // front_by_product(); elsewhere every neighbour counts.
    //
    // The front is asked for twice a step and moves by a few rings between
    // two calls, while a pass over the rows of all upper nodes costs as
    // much as a product with K. So only the nodes near the last front and
    // near the nodes that changed set since are tested
    // (front_candidates()); the first call on a mesh tests every node.
    const auto on_front = [&](const unsigned int i) {
      bool next_to_lower = false;
      if (status[i] == BoundStatus::upper)
        for_each_neighbour(i, rows, [&](const unsigned int j) {
          next_to_lower = (status[j] != BoundStatus::upper);
          return next_to_lower;
        });
      return next_to_lower;
    };
    std::vector<unsigned int> front;
    if (rows_of_last_front != &rows
        || upper_at_last_front.size() != dofs.size())
      {
        upper_at_last_front.resize(dofs.size());
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            upper_at_last_front[i] = (status[i] == BoundStatus::upper);
            if (on_front(i))
              front.push_back(i);
          }
      }
    else
      for (const unsigned int i : front_candidates(rows))
        if (on_front(i))
          front.push_back(i);
    rows_of_last_front = &rows;
    last_front         = front;
    return front;
  }



  std::vector<unsigned int>
  DamageBounds::front_candidates(const OwnedRows &rows)
  {
    // A node that joined the front since the last call is upper and next
    // to a node below 1. Either it was not upper then, or that neighbour
    // was, and then the neighbour changed set and the node is in its row
    // (the graph of K is symmetric). So the last front, the nodes that
    // entered or left the upper set (found against the upper set recorded
    // then, one byte per node, which is brought up to date here) and every
    // entry of their rows hold the new front.
    std::vector<unsigned int> candidates = std::move(last_front);
    const unsigned int *const columns    = rows.columns().data();
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (const char upper = (status[i] == BoundStatus::upper);
          upper != upper_at_last_front[i])
        {
          upper_at_last_front[i] = upper;
          candidates.push_back(i);
          const unsigned int row = owned_position[i];
          for (unsigned int e = rows.row_start()[row];
               e < rows.row_start()[row + 1];
               ++e)
            if (columns[e] < node_of_owned.size()
                && node_of_owned[columns[e]] >= 0)
              candidates.push_back(node_of_owned[columns[e]]);
        }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()),
                     candidates.end());
    return candidates;
  }



  std::vector<unsigned int>
  DamageBounds::free_next_ring(const std::vector<unsigned int> &ring,
                               const OwnedRows                 &rows)
  {
    // Every upper node next to a node below 1 was on the front, and is
    // free now: the next front lies next to the ring just freed.
    std::vector<unsigned int> next;
    for (const unsigned int i : ring)
      for_each_neighbour(i, rows, [&](const unsigned int j) {
        if (status[j] == BoundStatus::upper)
          {
            status[j] = BoundStatus::free;
            next.push_back(j);
          }
        return false;
      });
    return next;
  }



  void
  DamageBounds::begin_step(SupportProduct &product)
  {
    upper_at_start.resize(dofs.size());
    for (unsigned int i = 0; i < dofs.size(); ++i)
      upper_at_start[i] = (status[i] == BoundStatus::upper);
    front_size
      = Utilities::MPI::sum(static_cast<unsigned int>(front(product).size()),
                            communicator);
  }



  double
  DamageBounds::rings_moved() const
  {
    unsigned int n_left = 0;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      n_left
        += (owned[i] && upper_at_start[i] && status[i] != BoundStatus::upper);
    n_left = Utilities::MPI::sum(n_left, communicator);
    return (front_size > 0 ? static_cast<double>(n_left) / front_size : 0.);
  }



  unsigned int
  DamageBounds::free_ahead_of_front(SupportProduct    &product,
                                    const unsigned int rings)
  {
    // The first ring is the front; on one rank each further ring is found
    // next to the one before, on several by the product again (a ring may
    // continue across the cut between ranks).
    const bool one_rank = (Utilities::MPI::n_mpi_processes(communicator) == 1);
    unsigned int              n_freed = 0;
    std::vector<unsigned int> ring;
    for (unsigned int r = 0; r < rings; ++r)
      {
        if (r == 0 || !one_rank)
          {
            ring = front(product);
            for (const unsigned int i : ring)
              status[i] = BoundStatus::free;
          }
        else
          ring = free_next_ring(ring, product.rows());
        n_freed += ring.size();
      }
    return Utilities::MPI::sum(n_freed, communicator);
  }



  const std::vector<BoundStatus> &
  DamageBounds::sets() const
  {
    return status;
  }



  void
  DamageBounds::restore_sets(const std::vector<BoundStatus> &saved)
  {
    AssertDimension(saved.size(), status.size());
    status = saved;
  }



  std::pair<unsigned int, unsigned int>
  DamageBounds::count() const
  {
    unsigned int n_lower = 0, n_upper = 0;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (owned[i])
        {
          n_lower += (status[i] == BoundStatus::lower);
          n_upper += (status[i] == BoundStatus::upper);
        }
    return {Utilities::MPI::sum(n_lower, communicator),
            Utilities::MPI::sum(n_upper, communicator)};
  }



  void
  DamageBounds::write_state(LA::MPI::Vector &state) const
  {
    for (unsigned int i = 0; i < dofs.size(); ++i)
      if (owned[i])
        state(dofs[i]) = static_cast<double>(static_cast<int>(status[i]));
    state.compress(VectorOperation::insert);
  }



  void
  DamageBounds::read_state(const LA::MPI::Vector &state,
                           const bool             interpolated)
  {
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        double value = state(dofs[i]);
        // A new node between a bound node and a free one (or one at the
        // other bound) starts free: the bound iteration of the next step
        // puts it back on a bound if it belongs there.
        if (interpolated && value != -1. && value != 1.)
          value = 0.;
        AssertThrow(value == -1. || value == 0. || value == 1.,
                    ExcMessage("The checkpoint holds no valid damage bound "
                               "state at damage degree of freedom "
                               + std::to_string(dofs[i]) + "."));
        status[i] = static_cast<BoundStatus>(static_cast<int>(value));
      }
  }
} // namespace VPContact
