// The values stored at the quadrature points of a cell, carried to its
// children when it is refined and to its parent when they are coarsened.
#ifndef vpcontact_quadrature_field_transfer_h
#define vpcontact_quadrature_field_transfer_h

#include <deal.II/base/quadrature.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Quadrature point data as a discontinuous field. On a quadrilateral
   * (hexahedron) the n^dim points of the tensor-product Gauss rule carry
   * one polynomial of degree n - 1 in each variable, the Lagrange
   * interpolant through the points (FE_DGQArbitraryNodes with the Gauss
   * points as nodes, the space that STYLE.md suggests for the stress).
   * The transfer works on that field:
   *
   * - refinement evaluates the parent's polynomial at each child's points:
   *   a field the coarse mesh represents comes through unchanged;
   * - coarsening is the L2 projection of the children's fields onto the
   *   parent's polynomials, in the reference coordinates of the parent.
   *   The Gauss rule integrates the products of two such polynomials
   *   exactly, so the parent's mass matrix is diagonal (the weights) and
   *   the projection of each value is one sum over the children's points.
   *   It keeps the mean of each value over the parent, and refining the
   *   projected field and coarsening again gives it back.
   *
   * Every value of a point (stress components, predictor, damage source,
   * initial rate) is transferred on its own, by the same matrices. Only
   * isotropic refinement of hypercube cells, which p4est makes, is
   * supported; the child numbering is deal.II's lexicographic one.
   */
  template <int dim>
  class QuadratureFieldTransfer
  {
  public:
    /// For the rule @p quadrature, a tensor product of a one-dimensional
    /// Gauss rule on the unit hypercube.
    explicit QuadratureFieldTransfer(const Quadrature<dim> &quadrature);

    /// The number of children of a refined cell.
    static constexpr unsigned int n_children = 1u << dim;

    /**
     * The values at the points of child @p child from those of its parent:
     * @p parent holds n_points blocks of @p n_values values, and so does
     * @p values on return.
     */
    void
    refine(const std::vector<double> &parent,
           const unsigned int         n_values,
           const unsigned int         child,
           std::vector<double>       &values) const;

    /**
     * The values at the parent's points from those of its children, the
     * blocks of each child (as refine() lays them out) one after the other
     * in @p children.
     */
    void
    coarsen(const std::vector<double> &children,
            const unsigned int         n_values,
            std::vector<double>       &parent) const;

    unsigned int
    n_points() const;

  private:
    /// child_values[c](q', q): the parent's q-th Lagrange polynomial at the
    /// q'-th point of child c.
    std::vector<FullMatrix<double>> child_values;
    /// The reference weights of the rule.
    std::vector<double> weights;
  };
} // namespace VPContact

#endif
