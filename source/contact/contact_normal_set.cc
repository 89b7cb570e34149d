// The contact and separation sets of unilateral (Signorini) contact, and the
// bounds of Coulomb friction: the members of FrictionActiveSet for the
// normal part of the contact conditions.
#include <vpcontact/contact/friction_active_set.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace VPContact
{
  template <int dim>
  bool
  FrictionActiveSet<dim>::make_unilateral_node(
    const AffineConstraints<double> &base_constraints,
    Node                            &node) const
  {
    // In contact, the node holds u.nu = g_0 through its component d with
    // the largest |nu_d| (the best conditioned of the possible choices);
    // a node whose component d the boundary conditions hold is no contact
    // node (the clamp or roller wins).
    unsigned int d = 0;
    for (unsigned int e = 1; e < dim; ++e)
      if (std::abs(node.normal[e]) > std::abs(node.normal[d]))
        d = e;
    node.normal_component = d;
    if (base_constraints.is_constrained(node.dofs[d]))
      return false;

    // Moving a free component u_f by 1 moves u_d by -nu_f / nu_d, so the
    // node by e_f - (nu_f / nu_d) e_d, normal to nu. Gram-Schmidt turns
    // these motions into an orthonormal basis of the tangent space; a node
    // whose other components are all held has none (and no friction).
    for (unsigned int f = 0; f < dim; ++f)
      if (f != d && !base_constraints.is_constrained(node.dofs[f]))
        {
          node.free_dofs.push_back(node.dofs[f]);
          Tensor<1, dim> t;
          t[f] = 1.;
          t[d] = -node.normal[f] / node.normal[d];
          for (const auto &earlier : node.tangents)
            t -= (t * earlier) * earlier;
          node.tangents.push_back(t / t.norm());
        }
    return true;
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::add_contact_constraints(
    AffineConstraints<double> &constraints,
    const LA::MPI::Vector     *previous) const
  {
    // nu . (u_{n-1} + du) = g_0 solved for du_d:
    //   du_d = (g_0 - nu . u_{n-1}) / nu_d - sum_{e != d} (nu_e / nu_d) du_e.
    if (!unilateral)
      return;
    for (const auto &node : nodes)
      if (node.status != ContactStatus::separated)
        {
          const unsigned int d   = node.normal_component;
          const auto         dof = node.dofs[d];
          if (constraints.is_constrained(dof))
            continue;
          double normal_displacement = 0;
          if (previous)
            for (unsigned int e = 0; e < dim; ++e)
              normal_displacement += node.normal[e] * (*previous)(node.dofs[e]);
          constraints.add_line(dof);
          for (unsigned int e = 0; e < dim; ++e)
            if (e != d && node.normal[e] != 0.)
              constraints.add_entry(dof,
                                    node.dofs[e],
                                    -node.normal[e] / node.normal[d]);
          constraints.set_inhomogeneity(dof,
                                        (node.initial_gap - normal_displacement)
                                          / node.normal[d]);
        }
  }



  template <int dim>
  bool
  FrictionActiveSet<dim>::decide_contact(Node &node, const double c) const
  {
    // p = max(0, p - c d) holds with p >= 0, d >= 0 and p d = 0: the node
    // is in contact where p - c d > 0. In contact d is 0 up to round-off
    // and the pressure decides; separated, p is the residual of a free
    // degree of freedom, 0 up to the solver's tolerance, and the gap
    // decides.
    const bool was_in_contact = (node.status != ContactStatus::separated);
    const bool in_contact     = (node.pressure - c * node.gap > 0);
    if (in_contact == was_in_contact)
      return false;
    // A node that comes into contact starts in the stick set.
    node.status = in_contact ? ContactStatus::stick : ContactStatus::separated;
    node.direction      = TangentVector();
    node.slip_stiffness = 0;
    return true;
  }



  template <int dim>
  bool
  FrictionActiveSet<dim>::update_bound(Node                      &node,
                                       const TrescaFriction<dim> &law,
                                       const double               scale) const
  {
    // Coulomb: g = mu |sigma_nu| from this iterate's pressure (tension
    // carries no friction). Tresca's bound is given.
    if (!coulomb)
      return false;
    const double g     = node.mu * std::max(node.pressure, 0.);
    const bool   moved = std::abs(g - node.g) > law.bound_tolerance() * scale;
    node.g             = g;
    return moved;
  }



  template <int dim>
  typename FrictionActiveSet<dim>::NormalMeasures
  FrictionActiveSet<dim>::normal_measures() const
  {
    // The pressure's violations are relative to the stress scale of
    // max_violation(), the gap's are lengths.
    NormalMeasures measures;
    Tensor<1, dim> friction_force;
    double         stress_scale = 0;
    for (const auto &node : nodes)
      if (node.owned)
        stress_scale = std::max({stress_scale, node.g, node.traction});
    stress_scale       = Utilities::MPI::max(stress_scale, communicator);
    const double scale = (stress_scale > 0 ? stress_scale : 1.);
    for (const auto &node : nodes)
      if (node.owned)
        {
          if (node.status == ContactStatus::separated)
            {
              ++measures.n_separated;
              measures.pressure_violation
                = std::max(measures.pressure_violation,
                           std::abs(node.pressure) / scale);
              measures.gap_violation
                = std::max(measures.gap_violation, -node.gap);
              continue;
            }
          ++measures.n_contact;
          measures.contact_measure += node.length;
          if (node.status == ContactStatus::stick)
            measures.stick_measure += node.length;
          measures.max_pressure
            = std::max(measures.max_pressure, node.pressure);
          measures.normal_force += node.length * node.pressure;
          friction_force += node.length * node.vector(node.lambda);
          measures.pressure_violation
            = std::max(measures.pressure_violation, -node.pressure / scale);
          measures.gap_violation
            = std::max(measures.gap_violation, std::abs(node.gap));
        }
    measures.n_contact = Utilities::MPI::sum(measures.n_contact, communicator);
    measures.n_separated
      = Utilities::MPI::sum(measures.n_separated, communicator);
    measures.contact_measure
      = Utilities::MPI::sum(measures.contact_measure, communicator);
    measures.stick_measure
      = Utilities::MPI::sum(measures.stick_measure, communicator);
    measures.max_pressure
      = Utilities::MPI::max(measures.max_pressure, communicator);
    measures.normal_force
      = Utilities::MPI::sum(measures.normal_force, communicator);
    for (unsigned int d = 0; d < dim; ++d)
      friction_force[d] = Utilities::MPI::sum(friction_force[d], communicator);
    measures.tangential_force = friction_force.norm();
    measures.pressure_violation
      = Utilities::MPI::max(measures.pressure_violation, communicator);
    measures.gap_violation
      = Utilities::MPI::max(measures.gap_violation, communicator);
    return measures;
  }



  template <int dim>
  void
  FrictionActiveSet<dim>::fill_normal_output(LA::MPI::Vector &normal) const
  {
    normal = 0.;
    for (const auto &node : nodes)
      if (node.owned)
        {
          normal(node.dofs[0]) = node.pressure;
          normal(node.dofs[1]) = node.gap;
        }
    normal.compress(VectorOperation::insert);
  }



  template <int dim>
  bool
  FrictionActiveSet<dim>::keep_one_stick()
  {
    // The smallest excess over all ranks, then the lowest dof that has it:
    // every rank picks the same node.
    double excess = std::numeric_limits<double>::max();
    for (const auto &node : nodes)
      if (node.owned && node.status == ContactStatus::slip)
        excess = std::min(excess, node.excess);
    excess = Utilities::MPI::min(excess, communicator);
    if (excess == std::numeric_limits<double>::max())
      return false;
    types::global_dof_index dof = numbers::invalid_dof_index;
    for (const auto &node : nodes)
      if (node.owned && node.status == ContactStatus::slip
          && node.excess == excess)
        dof = std::min(dof, node.dofs[0]);
    dof = Utilities::MPI::min(dof, communicator);
    for (auto &node : nodes)
      if (node.dofs[0] == dof)
        {
          node.status         = ContactStatus::stick;
          node.direction      = TangentVector();
          node.slip_stiffness = 0;
        }
    return true;
  }



  template <int dim>
  unsigned long long
  FrictionActiveSet<dim>::fingerprint() const
  {
    // A hash of each owned node's global index, status and (in 2D) slip
    // direction, summed over the nodes and ranks: the order of the nodes
    // does not matter.
    unsigned long long sum = 0;
    for (const auto &node : nodes)
      if (node.owned)
        {
          // In 3D a direction turns continuously and is no set.
          const double sign = (dim == 2 && node.status == ContactStatus::slip) ?
                                (node.direction[0] > 0 ? 1. : -1.) :
                                0.;
          unsigned long long h = node.dofs[0] * 0x9E3779B97F4A7C15ULL;
          h ^= (static_cast<unsigned long long>(node.status) * 4
                + static_cast<unsigned long long>(sign + 1))
               * 0xC2B2AE3D27D4EB4FULL;
          h ^= h >> 29;
          sum += h;
        }
    return Utilities::MPI::sum(sum, communicator);
  }



  template class FrictionActiveSet<2>;
  template class FrictionActiveSet<3>;
} // namespace VPContact
