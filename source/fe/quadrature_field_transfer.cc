// Quadrature point data through refinement and coarsening, as a
// discontinuous polynomial field through the Gauss points.
#include <vpcontact/fe/quadrature_field_transfer.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>

#include <cmath>

namespace VPContact
{
  namespace
  {
    // The one-dimensional rule of which @p quadrature is the tensor
    // product: its distinct first coordinates, which QGauss<dim> lists
    // lexicographically with x running fastest.
    template <int dim>
    std::vector<double>
    coordinates_1d(const Quadrature<dim> &quadrature)
    {
      const unsigned int n = static_cast<unsigned int>(
        std::lround(std::pow(quadrature.size(), 1. / dim)));
      AssertThrow(std::pow(n, dim) == quadrature.size(),
                  ExcMessage("QuadratureFieldTransfer needs a tensor-product "
                             "rule on quadrilaterals (hexahedra)."));
      std::vector<double> x(n);
      for (unsigned int i = 0; i < n; ++i)
        x[i] = quadrature.point(i)[0];
      return x;
    }
  } // namespace



  template <int dim>
  QuadratureFieldTransfer<dim>::QuadratureFieldTransfer(
    const Quadrature<dim> &quadrature)
    : weights(quadrature.get_weights())
  {
    const std::vector<double> x = coordinates_1d(quadrature);
    const unsigned int        n = x.size();
    std::vector<Point<1>>     nodes;
    for (const double xi : x)
      nodes.emplace_back(xi);
    const auto lagrange = Polynomials::generate_complete_Lagrange_basis(nodes);

    // Point q of the rule has the one-dimensional indices (q mod n,
    // (q / n) mod n, ...); check that the rule is laid out so.
    const auto index = [n](unsigned int q, const unsigned int d) {
      for (unsigned int e = 0; e < d; ++e)
        q /= n;
      return q % n;
    };
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      for (unsigned int d = 0; d < dim; ++d)
        AssertThrow(std::abs(quadrature.point(q)[d] - x[index(q, d)]) < 1e-14,
                    ExcMessage("QuadratureFieldTransfer needs a "
                               "lexicographic tensor-product rule."));

    // Child c covers [b_d / 2, (b_d + 1) / 2] in direction d, b_d the d-th
    // bit of c; its point q' sits at (b_d + x_q') / 2.
    child_values.assign(n_children,
                        FullMatrix<double>(quadrature.size(),
                                           quadrature.size()));
    for (unsigned int c = 0; c < n_children; ++c)
      for (unsigned int qc = 0; qc < quadrature.size(); ++qc)
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            double value = 1;
            for (unsigned int d = 0; d < dim; ++d)
              value *= lagrange[index(q, d)].value(
                (((c >> d) & 1u) + x[index(qc, d)]) / 2);
            child_values[c](qc, q) = value;
          }
  }



  template <int dim>
  void
  QuadratureFieldTransfer<dim>::refine(const std::vector<double> &parent,
                                       const unsigned int         n_values,
                                       const unsigned int         child,
                                       std::vector<double>       &values) const
  {
    const unsigned int n_q = weights.size();
    AssertDimension(parent.size(), n_q * n_values);
    values.assign(n_q * n_values, 0.);
    const FullMatrix<double> &P = child_values[child];
    for (unsigned int qc = 0; qc < n_q; ++qc)
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int v = 0; v < n_values; ++v)
          values[qc * n_values + v] += P(qc, q) * parent[q * n_values + v];
  }



  template <int dim>
  void
  QuadratureFieldTransfer<dim>::coarsen(const std::vector<double> &children,
                                        const unsigned int         n_values,
                                        std::vector<double>       &parent) const
  {
    // a_q = (1 / w_q) sum_c sum_q' L_q(x_c,q') (w_q' / 2^dim) v_c,q'.
    const unsigned int n_q = weights.size();
    AssertDimension(children.size(), n_children * n_q * n_values);
    parent.assign(n_q * n_values, 0.);
    for (unsigned int c = 0; c < n_children; ++c)
      for (unsigned int qc = 0; qc < n_q; ++qc)
        {
          const double *v = &children[(c * n_q + qc) * n_values];
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const double factor = child_values[c](qc, q) * weights[qc]
                                    / n_children / weights[q];
              for (unsigned int i = 0; i < n_values; ++i)
                parent[q * n_values + i] += factor * v[i];
            }
        }
  }



  template <int dim>
  unsigned int
  QuadratureFieldTransfer<dim>::n_points() const
  {
    return weights.size();
  }



  template class QuadratureFieldTransfer<2>;
  template class QuadratureFieldTransfer<3>;
} // namespace VPContact
