// The primal-dual active set for Tresca friction: contact nodes, their
// stick/slip decisions, and their constraints and forces.
#include <vpcontact/contact/boundary_measures.h>
#include <vpcontact/contact/friction_active_set.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>

namespace VPContact
{



  template <int dim>
  void
  FrictionActiveSet<dim>::setup(
    const DoFHandler<dim>              &dof_handler,
    const AffineConstraints<double>    &base_constraints,
    const std::set<types::boundary_id> &contact_ids,
    const IndexSet                     &locally_relevant_dofs,
    const TrescaFriction<dim>          &law)
  {
    communicator = dof_handler.get_communicator();
    unilateral   = law.unilateral();
    coulomb = (law.friction_law() == TrescaFriction<dim>::FrictionLaw::coulomb);
    nodes.clear();
    const IndexSet &owned_dofs = dof_handler.locally_owned_dofs();
    const auto      on_contact = [&](const auto &face) {
      return face->at_boundary() && contact_ids.count(face->boundary_id()) == 1;
    };

    const LA::MPI::Vector relevant_lengths
      = lumped_lengths(dof_handler, contact_ids, locally_relevant_dofs);
    // The body's outward normal at each node, unless the foundation gives
    // one (unilateral contact needs it before the node is made).
    const LA::MPI::Vector relevant_normals
      = lumped_normals(dof_handler, contact_ids, locally_relevant_dofs);

    // The nodes, on every cell this rank sees (owned or ghost).
    std::set<types::global_dof_index> seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          if (on_contact(face))
            for (const unsigned int v : face->vertex_indices())
              {
                Node node;
                if (!seen.insert(face->vertex_dof_index(v, 0)).second)
                  continue;
                for (unsigned int d = 0; d < dim; ++d)
                  node.normal[d]
                    = relevant_normals(face->vertex_dof_index(v, d));
                node.normal = law.foundation_normal().value_or(
                  node.normal / node.normal.norm());
                if (!make_node(face, v, base_constraints, node))
                  continue;
                // All components of a vertex have one owner.
                node.owned  = owned_dofs.is_element(node.dofs[0]);
                node.length = relevant_lengths(node.dofs[0]);
                // With unilateral contact, the nodes that touch the
                // foundation at t = 0 start in contact, the others
                // separated: a cylinder on a plane starts from one line.
                if (unilateral)
                  {
                    node.initial_gap = law.initial_gap(node.position, 0.);
                    if (node.initial_gap > 0)
                      node.status = ContactStatus::separated;
                  }
                nodes.push_back(node);
              }
  }



  template <int dim>
  bool
  FrictionActiveSet<dim>::make_node(
    const typename DoFHandler<dim>::face_iterator &face,
    const unsigned int                             v,
    const AffineConstraints<double>               &base_constraints,
    Node                                          &node) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      node.dofs[d] = face->vertex_dof_index(v, d);
    node.position = face->vertex(v);
    if (unilateral)
      return make_unilateral_node(base_constraints, node);

    // At least one free component and at least one held by the bilateral
    // condition; none free means a Dirichlet part holds the node (the clamp
    // wins).
    std::vector<unsigned int> free_components;
    for (unsigned int d = 0; d < dim; ++d)
      if (!base_constraints.is_constrained(node.dofs[d]))
        {
          free_components.push_back(d);
          node.free_dofs.push_back(node.dofs[d]);
        }
    if (free_components.empty() || free_components.size() == dim)
      return false;

    // The constrained components a follow u_a = sum_f c_af u_f; moving u_f
    // by 1 moves the node by e_f + sum_a c_af e_a. Gram-Schmidt turns these
    // motions into an orthonormal basis of the tangent space.
    for (const unsigned int f : free_components)
      {
        Tensor<1, dim> t;
        t[f] = 1.;
        for (unsigned int a = 0; a < dim; ++a)
          if (const auto *entries
              = base_constraints.get_constraint_entries(node.dofs[a]))
            for (const auto &[dof, coefficient] : *entries)
              if (dof == node.dofs[f])
                t[a] = coefficient;
        for (const auto &earlier : node.tangents)
          t -= (t * earlier) * earlier;
        node.tangents.push_back(t / t.norm());
      }
    return true;
  }



  template <int dim>
  typename FrictionActiveSet<dim>::TangentVector
  FrictionActiveSet<dim>::Node::coordinates(const Tensor<1, dim> &v) const
  {
    TangentVector c;
    for (unsigned int k = 0; k < tangents.size(); ++k)
      c[k] = v * tangents[k];
    return c;
  }



  template <int dim>
  Tensor<1, dim>
  FrictionActiveSet<dim>::Node::vector(const TangentVector &c) const
  {
    Tensor<1, dim> v;
    for (unsigned int k = 0; k < tangents.size(); ++k)
      v += c[k] * tangents[k];
    return v;
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::set_bounds(const TrescaFriction<dim> &friction,
                                     const double               time)
  {
    // Coulomb's bounds stay those of the last iterate (the warm start);
    // its coefficient is that of this step's time.
    for (auto &node : nodes)
      {
        if (coulomb)
          node.mu = friction.coefficient(node.position, time);
        else
          node.g = friction.bound(node.position, time);
        if (unilateral)
          node.initial_gap = friction.initial_gap(node.position, time);
      }
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::add_stick_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const auto &node : nodes)
      if (node.status == ContactStatus::stick)
        for (const auto dof : node.free_dofs)
          if (!constraints.is_constrained(dof))
            constraints.add_line(dof);
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::add_slip_forces(
    const AffineConstraints<double> &constraints,
    LA::MPI::Vector                 &rhs) const
  {
    // At a slip node the residual must be m_i lambda_i with
    // lambda_i = g_i n_i (plus the slip stiffness term, which the matrix
    // carries), i.e. the system gets the force -m_i g_i n_i.
    Vector<double>                       force(dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (const auto &node : nodes)
      if (node.owned && node.status == ContactStatus::slip)
        {
          const Tensor<1, dim> n = node.vector(node.direction);
          for (unsigned int d = 0; d < dim; ++d)
            {
              force(d) = -node.length * node.g * n[d];
              dofs[d]  = node.dofs[d];
            }
          constraints.distribute_local_to_global(force, dofs, rhs);
        }
    rhs.compress(VectorOperation::add);
  }



  template <int dim>
  FullMatrix<double>
  FrictionActiveSet<dim>::Node::slip_stiffness_matrix(const TangentVector &n,
                                                      const double beta) const
  {
    // m beta (P - n n^T) with P = sum_k t_k t_k^T; on a tangent line
    // P = n n^T and the matrix is zero.
    const Tensor<1, dim> n_vector = vector(n);
    FullMatrix<double>   stiffness(dim, dim);
    for (const auto &t : tangents)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          stiffness(i, j) += t[i] * t[j];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        stiffness(i, j)
          = length * beta * (stiffness(i, j) - n_vector[i] * n_vector[j]);
    return stiffness;
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::add_slip_stiffness(
    const AffineConstraints<double> &constraints,
    LA::SparseMatrix                &matrix)
  {
    // The constraints carry the node's stiffness over to its free degrees
    // of freedom.
    std::vector<types::global_dof_index> dofs;
    for (auto &node : nodes)
      {
        const bool slips         = node.status == ContactStatus::slip;
        node.assembled_direction = slips ? node.direction : TangentVector();
        node.assembled_stiffness = slips ? node.slip_stiffness : 0.;
        if (node.owned && slips && node.tangents.size() > 1)
          {
            dofs.assign(node.dofs.begin(), node.dofs.end());
            constraints.distribute_local_to_global(
              node.slip_stiffness_matrix(node.direction, node.slip_stiffness),
              dofs,
              matrix);
          }
      }
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::update_slip_stiffness(
    const AffineConstraints<double> &constraints,
    LA::SparseMatrix                &matrix)
  {
    // No set changed, so the constraints are those the matrix was built
    // with, and the new stiffness minus the one the matrix holds is the
    // whole change. Every rank tracks what the matrix holds for the nodes
    // it sees; the owner adds the change.
    std::vector<types::global_dof_index> dofs;
    for (auto &node : nodes)
      if (node.status == ContactStatus::slip && node.tangents.size() > 1
          && (node.direction != node.assembled_direction
              || node.slip_stiffness != node.assembled_stiffness))
        {
          if (node.owned)
            {
              FullMatrix<double> change
                = node.slip_stiffness_matrix(node.direction,
                                             node.slip_stiffness);
              change.add(-1.,
                         node.slip_stiffness_matrix(node.assembled_direction,
                                                    node.assembled_stiffness));
              dofs.assign(node.dofs.begin(), node.dofs.end());
              constraints.distribute_local_to_global(change, dofs, matrix);
            }
          node.assembled_direction = node.direction;
          node.assembled_stiffness = node.slip_stiffness;
        }
    matrix.compress(VectorOperation::add);
  }



  template <int dim>
  double
  FrictionActiveSet<dim>::measure(const LA::MPI::Vector &residual,
                                  const LA::MPI::Vector &increment,
                                  const LA::MPI::Vector &previous)
  {
    double bound_scale = 0;
    for (auto &node : nodes)
      {
        Tensor<1, dim> r, du, u;
        for (unsigned int d = 0; d < dim; ++d)
          {
            r[d]  = residual(node.dofs[d]);
            du[d] = increment(node.dofs[d]);
            u[d]  = previous(node.dofs[d]) + du[d];
          }
        node.lambda   = node.coordinates(r) / node.length;
        node.traction = r.norm() / node.length;
        node.slip     = node.coordinates(du);
        node.pressure = (r * node.normal) / node.length;
        node.gap      = unilateral ? node.initial_gap - u * node.normal : 0.;
        if (node.owned)
          bound_scale
            = std::max(bound_scale, node.mu * std::max(node.pressure, 0.));
      }
    return Utilities::MPI::max(bound_scale, communicator);
  }



  template <int dim>
  typename FrictionActiveSet<dim>::Changes
  FrictionActiveSet<dim>::update(const LA::MPI::Vector     &residual,
                                 const LA::MPI::Vector     &increment,
                                 const LA::MPI::Vector     &previous,
                                 const double               youngs_modulus,
                                 const TrescaFriction<dim> &law)
  {
    // The multipliers, slips and gaps of this iterate at every node first:
    // Coulomb's bounds are compared with the largest of them.
    const double bound_scale = measure(residual, increment, previous);
    Changes      changes;
    for (auto &node : nodes)
      {
        const double c
          = complementarity_constant<dim>(law.complementarity_factor(),
                                          youngs_modulus,
                                          node.length);
        if (unilateral && decide_contact(node, c))
          {
            if (node.owned)
              {
                ++changes.n_changed;
                ++changes.n_stick_changed;
                ++changes.n_matrix_changed;
              }
            continue;
          }
        if (node.status == ContactStatus::separated)
          continue;
        const bool moved = update_bound(node, law, bound_scale);
        const auto next  = tresca_decision(node.lambda, node.slip, node.g, c);
        node.excess      = (node.lambda + c * node.slip).norm() - node.g;
        const bool stick_changed = (next.status != node.status);
        const bool turned        = next.status == ContactStatus::slip
                            && (stick_changed
                                || (next.direction - node.direction).norm()
                                     > law.direction_tolerance());
        const bool stiffer = next.status == ContactStatus::slip && moved;
        if (node.owned)
          {
            changes.n_changed += stick_changed || turned || moved;
            changes.n_bounds_moved += moved;
            changes.n_stick_changed += stick_changed;
            changes.n_matrix_changed
              += stick_changed
                 || ((turned || stiffer) && node.tangents.size() > 1);
          }
        node.status = next.status;
        if (stick_changed || turned || stiffer)
          {
            node.direction      = next.direction;
            node.slip_stiffness = next.slip_stiffness;
          }
      }
    changes.n_changed = Utilities::MPI::sum(changes.n_changed, communicator);
    changes.n_stick_changed
      = Utilities::MPI::sum(changes.n_stick_changed, communicator);
    changes.n_matrix_changed
      = Utilities::MPI::sum(changes.n_matrix_changed, communicator);
    changes.n_bounds_moved
      = Utilities::MPI::sum(changes.n_bounds_moved, communicator);
    return changes;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  FrictionActiveSet<dim>::count() const
  {
    unsigned int n_stick = 0, n_slip = 0;
    for (const auto &node : nodes)
      if (node.owned && node.status != ContactStatus::separated)
        (node.status == ContactStatus::stick ? n_stick : n_slip) += 1;
    return {Utilities::MPI::sum(n_stick, communicator),
            Utilities::MPI::sum(n_slip, communicator)};
  }



  template <int dim>
  double
  FrictionActiveSet<dim>::max_bound() const
  {
    double g = 0;
    for (const auto &node : nodes)
      if (node.owned)
        g = std::max(g, node.g);
    return Utilities::MPI::max(g, communicator);
  }



  template <int dim>
  double
  FrictionActiveSet<dim>::max_utilisation() const
  {
    // A slip node uses its whole bound, by the law: its |lambda| differs
    // from g by the round-off of the residual, which relative to a tiny g
    // is any number (how far it is from g is max_violation()'s business).
    // A stick node of a settled iteration has |lambda| <= g.
    double utilisation = 0;
    for (const auto &node : nodes)
      if (node.owned && node.g > 0 && node.status != ContactStatus::separated)
        utilisation = std::max(utilisation,
                               node.status == ContactStatus::slip ?
                                 1. :
                                 node.lambda.norm() / node.g);
    return Utilities::MPI::max(utilisation, communicator);
  }



  template <int dim>
  double
  FrictionActiveSet<dim>::max_violation(const double slip_tolerance) const
  {
    // The violation is measured against the stresses it is computed from:
    // lambda comes out of a residual whose round-off is relative to the
    // contact traction, so with g far below |sigma nu| no solver gets
    // |lambda| - g below round-off of g, though the answer is exact.
    double violation = 0, stress_scale = 0, w_scale = 0;
    for (const auto &node : nodes)
      if (node.owned)
        {
          stress_scale = std::max({stress_scale, node.g, node.traction});
          w_scale      = std::max(w_scale, node.slip.norm());
        }
    stress_scale = Utilities::MPI::max(stress_scale, communicator);
    w_scale      = Utilities::MPI::max(w_scale, communicator);
    for (const auto &node : nodes)
      if (node.owned && node.status != ContactStatus::separated)
        {
          violation      = std::max(violation, node.lambda.norm() - node.g);
          const double w = node.slip.norm();
          if (w > slip_tolerance * w_scale)
            violation = std::max(violation,
                                 (node.lambda - node.g / w * node.slip).norm());
        }
    violation = Utilities::MPI::max(violation, communicator);
    return stress_scale > 0 ? violation / stress_scale : violation;
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::fill_output(LA::MPI::Vector &status,
                                      LA::MPI::Vector &traction) const
  {
    status   = 0.;
    traction = 0.;
    for (const auto &node : nodes)
      if (node.owned)
        {
          status(node.dofs[0]) = static_cast<double>(node.status);
          // In 2D the scalar along the tangent, in 3D the vector.
          const Tensor<1, dim> sigma_tau = -node.vector(node.lambda);
          if (dim == 2)
            traction(node.dofs[0]) = -node.lambda[0];
          else
            for (unsigned int d = 0; d < dim; ++d)
              traction(node.dofs[d]) = sigma_tau[d];
        }
    status.compress(VectorOperation::insert);
    traction.compress(VectorOperation::insert);
  }



  template <int dim>
  bool
  FrictionActiveSet<dim>::empty() const
  {
    return Utilities::MPI::max(static_cast<unsigned int>(nodes.size()),
                               communicator)
           == 0;
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::write_state(LA::MPI::Vector &state) const
  {
    for (const auto &node : nodes)
      if (node.owned)
        {
          state(node.dofs[0]) = static_cast<double>(node.status);
          for (unsigned int k = 0; k < node.tangents.size(); ++k)
            state(node.dofs[k + 1]) = node.direction[k];
        }
    state.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::read_state(const LA::MPI::Vector &state,
                                     const bool             interpolated)
  {
    for (auto &node : nodes)
      {
        double        status = state(node.dofs[0]);
        TangentVector direction;
        for (unsigned int k = 0; k < node.tangents.size(); ++k)
          direction[k] = state(node.dofs[k + 1]);
        double size = direction.norm();
        // A new node between nodes of different sets starts in the stick
        // set, as every node of a run's first step does; one between two
        // slipping nodes slips in their mean direction.
        if (interpolated && status == 2. && size > 0.)
          {
            direction /= size;
            size = 1.;
          }
        else if (interpolated
                 && !((status == 1. || status == 3.) && size == 0.))
          {
            status    = 1.;
            direction = TangentVector();
            size      = 0.;
          }
        AssertThrow(((status == 1. || status == 3.) && size == 0.)
                      || (status == 2. && std::abs(size - 1.) < 1e-8),
                    ExcMessage("The checkpoint holds no valid stick/slip "
                               "state at the contact node at "
                               + std::to_string(node.position[0]) + ", "
                               + std::to_string(node.position[1])
                               + ": it was written for another contact "
                                 "boundary."));
        node.status    = static_cast<ContactStatus>(static_cast<int>(status));
        node.direction = direction;
        node.slip_stiffness = 0;
      }
  }



  template <int dim>
  IndexSet
  FrictionActiveSet<dim>::node_dofs(const types::global_dof_index n_dofs) const
  {
    // Sorted first: IndexSet::add_index() takes an index below the last
    // one in time linear in the set's size.
    std::vector<types::global_dof_index> indices;
    for (const auto &node : nodes)
      indices.insert(indices.end(), node.dofs.begin(), node.dofs.end());
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    IndexSet dofs(n_dofs);
    dofs.add_indices(indices.begin(), indices.end());
    dofs.compress();
    return dofs;
  }



  template class FrictionActiveSet<2>;
  template class FrictionActiveSet<3>;
} // namespace VPContact
