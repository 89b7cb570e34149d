// Whether the boundary conditions hold the body against every rigid motion.
#include <vpcontact/rigid_motions.h>

#include <deal.II/base/mpi.h>
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

    // Component and position of the displacement degrees of freedom of
    // @p needed on the locally owned and ghost cells, the position taken
    // from the centre of the body and scaled by its size so that
    // translations and rotations weigh alike. Only the constrained lines and
    // the degrees of freedom they refer to are needed, a small part of the
    // mesh: the others are not looked at.
    template <int dim>
    std::map<types::global_dof_index, std::pair<unsigned int, Point<dim>>>
    displacement_nodes(const DoFHandler<dim> &dof_handler,
                       const IndexSet        &needed)
    {
      const MPI_Comm            communicator = dof_handler.get_communicator();
      const FiniteElement<dim> &fe           = dof_handler.get_fe();
      const Mapping<dim>       &mapping
        = get_default_linear_mapping(dof_handler.get_triangulation());
      const std::vector<Point<dim>>       &unit = fe.get_unit_support_points();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, std::pair<unsigned int, Point<dim>>>
                 nodes;
      Point<dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::numeric_limits<double>::max();
          upper[d] = -lower[d];
        }
      // The body's bounding box from the cells' vertices: the support
      // points of the linear elements.
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < dim; ++d)
                {
                  lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                  upper[d] = std::max(upper[d], cell->vertex(v)[d]);
                }
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const unsigned int c = fe.system_to_component_index(i).first;
                if (c < dim && needed.is_element(dofs[i])
                    && nodes.count(dofs[i]) == 0)
                  nodes[dofs[i]]
                    = {c, mapping.transform_unit_to_real_cell(cell, unit[i])};
              }
          }
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = Utilities::MPI::min(lower[d], communicator);
          upper[d] = Utilities::MPI::max(upper[d], communicator);
        }
      const Point<dim> centre = 0.5 * (lower + upper);
      const double     size   = std::max(upper.distance(lower), 1e-300);
      for (auto &node : nodes)
        node.second.second = Point<dim>((node.second.second - centre) / size);
      return nodes;
    }

    // The owned constrained lines and the degrees of freedom they refer
    // to.
    IndexSet
    constrained_lines_and_parents(const IndexSet                  &owned,
                                  const AffineConstraints<double> &constraints)
    {
      std::vector<types::global_dof_index> indices;
      for (const auto &line : constraints.get_lines())
        if (owned.is_element(line.index))
          {
            indices.push_back(line.index);
            for (const auto &entry : line.entries)
              indices.push_back(entry.first);
          }
      std::sort(indices.begin(), indices.end());
      indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
      IndexSet set(owned.size());
      set.add_indices(indices.begin(), indices.end());
      set.compress();
      return set;
    }

    // The Gram matrix G = V^T V of the rigid motions (row by row), with
    // V_ik = r_k(i) - sum_j a_ij r_k(j) over the constrained displacement
    // lines i: c^T G c is how much the motion sum_k c_k r_k violates the
    // constraints. Each rank adds the lines it owns, skipping those that
    // refer to a degree of freedom it does not see; the sum is over all
    // ranks.
    template <int dim>
    std::vector<double>
    constrained_motions_gram(const DoFHandler<dim>           &dof_handler,
                             const AffineConstraints<double> &constraints,
                             const unsigned int               n_motions)
    {
      const IndexSet owned = dof_handler.locally_owned_dofs();
      const auto     nodes
        = displacement_nodes(dof_handler,
                             constrained_lines_and_parents(owned, constraints));
      const auto motion = [&](const unsigned int k, const auto &node) {
        return rigid_motion<dim>(k, node.second, node.first);
      };
      std::vector<double> gram(n_motions * n_motions, 0.);
      for (const auto &[dof, node] : nodes)
        if (owned.is_element(dof) && constraints.is_constrained(dof))
          {
            std::vector<double> v(n_motions);
            bool                known = true;
            for (unsigned int k = 0; k < n_motions; ++k)
              v[k] = motion(k, node);
            if (const auto *entries = constraints.get_constraint_entries(dof))
              for (const auto &[j, a] : *entries)
                {
                  const auto other = nodes.find(j);
                  known            = known && other != nodes.end();
                  if (other != nodes.end())
                    for (unsigned int k = 0; k < n_motions; ++k)
                      v[k] -= a * motion(k, other->second);
                }
            if (known)
              for (unsigned int k = 0; k < n_motions; ++k)
                for (unsigned int l = 0; l < n_motions; ++l)
                  gram[k * n_motions + l] += v[k] * v[l];
          }
      Utilities::MPI::sum(gram, dof_handler.get_communicator(), gram);
      return gram;
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
  void
  check_rigid_motions_held(const DoFHandler<dim>           &dof_handler,
                           const AffineConstraints<double> &constraints,
                           const std::string               &remedy)
  {
    constexpr unsigned int    n_motions = (dim == 2 ? 3 : 6);
    const std::vector<double> gram
      = constrained_motions_gram(dof_handler, constraints, n_motions);

    // The motion of the smallest eigenvalue is the one held least; one
    // held by nothing has the eigenvalue 0 (to round-off).
    Vector<double>     eigenvalues;
    FullMatrix<double> eigenvectors;
    const double       scale
      = eigen_decomposition(gram, n_motions, eigenvalues, eigenvectors);
    unsigned int weakest = 0;
    for (unsigned int m = 1; m < eigenvalues.size(); ++m)
      if (eigenvalues[m] < eigenvalues[weakest])
        weakest = m;
    if (scale > 0 && eigenvalues[weakest] > 1e-10 * scale)
      return;

    // Name the motion by its largest part.
    unsigned int largest = 0;
    for (unsigned int k = 1; k < n_motions; ++k)
      if (std::abs(eigenvectors(k, weakest))
          > std::abs(eigenvectors(largest, weakest)))
        largest = k;
    AssertThrow(false,
                ExcMessage("The body is not held: it can move as a rigid body ("
                           + motion_name(largest, dim)
                           + (std::abs(eigenvectors(largest, weakest)) < 0.99 ?
                                ", combined with other motions" :
                                "")
                           + ") without meeting any boundary condition, and "
                             "the displacement has no unique solution. "
                           + remedy));
  }



  template void
  check_rigid_motions_held(const DoFHandler<2> &,
                           const AffineConstraints<double> &,
                           const std::string &);
  template void
  check_rigid_motions_held(const DoFHandler<3> &,
                           const AffineConstraints<double> &,
                           const std::string &);
} // namespace VPContact
