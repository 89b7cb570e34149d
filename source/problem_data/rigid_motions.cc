// Whether the boundary conditions hold the body against every rigid motion.
#include <vpcontact/problem_data/rigid_motions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace VPContact
{
  namespace
  {
    // The value of rigid motion k at the point x for displacement component
    // c: the translations first, then the rotations (one in 2D, three in
    // 3D, about the axes through the origin).
    template <int dim>
    double
    rigid_motion(const unsigned int k,
                 const Point<dim>  &x,
                 const unsigned int c)
    {
      if (k < dim)
        return (c == k ? 1. : 0.);
      if (dim == 2)
        return (c == 0 ? -x[1] : x[0]);
      // Rotation about the axis a: (e_a x x)_c.
      const unsigned int a = k - dim, b = (a + 1) % 3, d = (a + 2) % 3;
      return (c == d ? x[b] : (c == b ? -x[d] : 0.));
    }

    std::string
    motion_name(const unsigned int k, const unsigned int dim)
    {
      const std::string axis[] = {"x", "y", "z"};
      if (k < dim)
        return "a translation in " + axis[k];
      return dim == 2 ? "a rotation" :
                        "a rotation about the " + axis[k - dim] + " axis";
    }

    // The eigenvalues and eigenvectors of the symmetric @p n x @p n matrix
    // @p gram (row by row). Returns its scale, the largest diagonal entry,
    // against which an eigenvalue counts as zero.
    double
    eigen_decomposition(const std::vector<double> &gram,
                        const unsigned int         n,
                        Vector<double>            &eigenvalues,
                        FullMatrix<double>        &eigenvectors)
    {
      LAPACKFullMatrix<double> matrix(n, n);
      double                   scale = 0;
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int l = 0; l < n; ++l)
          matrix(k, l) = gram[k * n + l];
      for (unsigned int k = 0; k < n; ++k)
        scale = std::max(scale, gram[k * n + k]);
      matrix.compute_eigenvalues_symmetric(-1. - scale,
                                           1. + n * scale,
                                           0.,
                                           eigenvalues,
                                           eigenvectors);
      return scale;
    }
  } // namespace



  template <int dim>
  RigidMotionCheck<dim>::RigidMotionCheck(const DoFHandler<dim> &dof_handler)
    : dof_handler(dof_handler)
    , mesh_parts(dof_handler)
  {}



  template <int dim>
  typename RigidMotionCheck<dim>::Nodes
  RigidMotionCheck<dim>::constrained_nodes(
    const AffineConstraints<double> &constraints) const
  {
    // The test reads only the owned constrained lines and the degrees of
    // freedom they refer to: boundary and hanging nodes, a small share of
    // the mesh. Only their support points are mapped, in one pass over the
    // cells this rank sees, so that a fine mesh pays for its boundary here
    // and not for all its nodes.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    IndexSet        needed(dof_handler.n_dofs());
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          needed.add_index(line.index);
          for (const auto &entry : line.entries)
            needed.add_index(entry.first);
        }
    needed.compress();

    // Positions from the centre of the node's part, scaled by the part's
    // size, so that translations and rotations weigh alike.
    Nodes                     nodes;
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    const Mapping<dim>       &mapping
      = get_default_linear_mapping(dof_handler.get_triangulation());
    const std::vector<Point<dim>>       &unit = fe.get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    if (needed.n_elements() > 0)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                if (c >= dim || !needed.is_element(dofs[i])
                    || nodes.count(dofs[i]) > 0)
                  continue;
                const auto [lower, upper]
                  = mesh_parts.bounding_box(mesh_parts.part_of(dofs[0]));
                const Point<dim> centre = 0.5 * (lower + upper);
                const double     size = std::max(upper.distance(lower), 1e-300);
                nodes[dofs[i]]
                  = {c,
                     Point<dim>(
                       (mapping.transform_unit_to_real_cell(cell, unit[i])
                        - centre)
                       / size)};
              }
          }
    return nodes;
  }



  template <int dim>
  std::vector<double>
  RigidMotionCheck<dim>::gram_matrices(
    const AffineConstraints<double> &constraints) const
  {
    // G = V^T V with V_ik = r_k(i) - sum_j a_ij r_k(j) over the constrained
    // displacement lines i of the part: c^T G c is how much the motion
    // sum_k c_k r_k of the part violates the constraints. Each rank adds the
    // lines it owns, skipping those that refer to a degree of freedom it
    // does not see; the sum is over all ranks.
    constexpr unsigned int n_motions = (dim == 2 ? 3 : 6);
    const IndexSet        &owned     = dof_handler.locally_owned_dofs();
    const auto motion = [&](const unsigned int k, const auto &node) {
      return rigid_motion<dim>(k, node.second, node.first);
    };
    const Nodes         nodes = constrained_nodes(constraints);
    std::vector<double> gram(mesh_parts.n_parts() * n_motions * n_motions, 0.);
    for (const auto &[dof, node] : nodes)
      if (owned.is_element(dof) && constraints.is_constrained(dof))
        {
          const unsigned int  part = mesh_parts.part_of(dof);
          std::vector<double> v(n_motions);
          bool                known = true;
          for (unsigned int k = 0; k < n_motions; ++k)
            v[k] = motion(k, node);
          if (const auto *entries = constraints.get_constraint_entries(dof))
            for (const auto &[j, a] : *entries)
              {
                const auto other = nodes.find(j);
                known            = known && other != nodes.end();
                if (other != nodes.end()
                    && mesh_parts.part_of(other->first) == part)
                  for (unsigned int k = 0; k < n_motions; ++k)
                    v[k] -= a * motion(k, other->second);
              }
          double *g = gram.data() + part * n_motions * n_motions;
          if (known)
            for (unsigned int k = 0; k < n_motions; ++k)
              for (unsigned int l = 0; l < n_motions; ++l)
                g[k * n_motions + l] += v[k] * v[l];
        }
    Utilities::MPI::sum(gram, dof_handler.get_communicator(), gram);
    return gram;
  }



  template <int dim>
  std::vector<std::pair<unsigned int, std::string>>
  RigidMotionCheck<dim>::free_motions(
    const AffineConstraints<double> &constraints) const
  {
    constexpr unsigned int    n_motions = (dim == 2 ? 3 : 6);
    const std::vector<double> all_grams = gram_matrices(constraints);
    std::vector<std::pair<unsigned int, std::string>> free;
    for (unsigned int part = 0; part < mesh_parts.n_parts(); ++part)
      {
        // The motion of the smallest eigenvalue is the one held least; one
        // held by nothing has the eigenvalue 0 (to round-off).
        const std::vector<double> gram(all_grams.begin()
                                         + part * n_motions * n_motions,
                                       all_grams.begin()
                                         + (part + 1) * n_motions * n_motions);
        Vector<double>            eigenvalues;
        FullMatrix<double>        eigenvectors;
        const double              scale
          = eigen_decomposition(gram, n_motions, eigenvalues, eigenvectors);
        unsigned int weakest = 0;
        for (unsigned int m = 1; m < eigenvalues.size(); ++m)
          if (eigenvalues[m] < eigenvalues[weakest])
            weakest = m;
        if (scale > 0 && eigenvalues[weakest] > 1e-10 * scale)
          continue;

        // Name the motion by its largest part.
        unsigned int largest = 0;
        for (unsigned int k = 1; k < n_motions; ++k)
          if (std::abs(eigenvectors(k, weakest))
              > std::abs(eigenvectors(largest, weakest)))
            largest = k;
        free.emplace_back(part,
                          motion_name(largest, dim)
                            + (std::abs(eigenvectors(largest, weakest)) < 0.99 ?
                                 ", combined with other motions" :
                                 ""));
      }
    return free;
  }



  template <int dim>
  void
  RigidMotionCheck<dim>::assert_held(
    const AffineConstraints<double> &constraints,
    const std::string               &remedy) const
  {
    const auto free = free_motions(constraints);
    if (free.empty())
      return;
    const auto &[part, motion] = free.front();
    const unsigned int n_parts = mesh_parts.n_parts();
    const std::string  what
      = (n_parts == 1 ? std::string("The body") :
                        "Part " + std::to_string(part + 1) + " of the "
                          + std::to_string(n_parts)
                          + " parts of the mesh that share no node, "
                          + mesh_parts.description(part) + ",");
    const std::string others
      = (free.size() > 1 ? " (and " + std::to_string(free.size() - 1)
                             + " more part(s) of the mesh)" :
                           std::string());
    AssertThrow(false,
                ExcMessage(what + " is not held" + others
                           + ": it can move as a rigid body (" + motion
                           + ") without meeting any boundary condition, and "
                             "the displacement has no unique solution. "
                           + remedy
                           + (n_parts == 1 ?
                                "" :
                                " Each part that shares no node with the "
                                "rest needs a hold of its own; if the parts "
                                "should be one body, join them in the mesh.")));
  }



  template <int dim>
  const MeshParts<dim> &
  RigidMotionCheck<dim>::parts() const
  {
    return mesh_parts;
  }



  template class RigidMotionCheck<2>;
  template class RigidMotionCheck<3>;
} // namespace VPContact
