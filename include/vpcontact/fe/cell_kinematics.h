// The strain and damage of a finite element vector at the quadrature points of
// every locally owned cell, and the work of a stress field on the cell's test
// functions, from shape gradients stored once per mesh instead of an FEValues
// reinitialized on every cell in every step.
#ifndef vpcontact_cell_kinematics_h
#define vpcontact_cell_kinematics_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <Epetra_BlockMap.h>
#include <memory>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * What the passes over all cells of every step need of a cell: for each
   * quadrature point the gradients of the scalar shape functions of the
   * element's base (Q1 or P1), the point itself, and where the cell's degrees
   * of freedom sit in the local storage of a ghosted vector. The element is the
   * simulator's FESystem: dim copies of one scalar element for the
   * displacement, and possibly one more for the damage.
   *
   * Why: the right-hand side and the stress update visit every cell in
   * every step. With FEValues each visit recomputes the
   * mapping (unless the previous cell was a translate of this one), copies
   * the shape data of the FESystem, and reads the cell's values through a
   * global-to-local index lookup per entry. What the visit needs is the
   * same in every step while the mesh is fixed, so it is computed once per
   * mesh here: the points and the entries' positions per cell, the
   * gradients once per shape of cell (one block for all cells of a box).
   *
   * The strain of a vector u at point q is
   * eps(u)(x_q) = sym(sum_a u_a (x) grad N_a(x_q)), with u_a the
   * displacement at node a; the work of a stress tau on the test function
   * phi_i = N_a e_c is tau(x_q) : eps(phi_i) = (tau(x_q) grad N_a(x_q))_c.
   */
  template <int dim>
  class CellKinematics
  {
  public:
    using cell_iterator = typename DoFHandler<dim>::active_cell_iterator;

    /**
     * Compute the data of every locally owned cell of @p dof_handler at the
     * points of @p quadrature. @p ghosted is a vector in the layout (the
     * Epetra map) of the vectors that will be read: their locally owned and
     * ghost entries.
     */
    void
    reinit(const DoFHandler<dim> &dof_handler,
           const Quadrature<dim> &quadrature,
           const LA::MPI::Vector &ghosted);

    /// The number of nodes (scalar shape functions) of a cell.
    unsigned int
    nodes_per_cell() const
    {
      return n_nodes;
    }

    /// The scalar element of every component (Q1 or P1).
    const FiniteElement<dim> &
    scalar_element() const
    {
      return *scalar;
    }

    /// Whether the element has a damage component (component dim).
    bool
    has_damage() const;

    /**
     * The local entries (owned and ghost) of @p vector, for the functions
     * below. Throws if @p vector is not in the layout given to reinit():
     * checked here once per pass rather than once per cell.
     */
    const double *
    local_entries(const LA::MPI::Vector &vector) const;

    /// The strain of the displacement of @p entries at the points of @p cell.
    void
    strains(const cell_iterator                 &cell,
            const double                        *entries,
            ArrayView<SymmetricTensor<2, dim>> &&strains) const;

    /// The damage (component dim) of @p entries at the points of @p cell.
    void
    damage(const cell_iterator &cell,
           const double        *entries,
           ArrayView<double>  &&damage) const;

    /// The gradient of the damage of @p entries at the points of @p cell.
    void
    damage_gradients(const cell_iterator        &cell,
                     const double               *entries,
                     ArrayView<Tensor<1, dim>> &&gradients) const;

    /// The value of scalar shape function @p a at point @p q (the same on
    /// every cell).
    double
    shape_value(const unsigned int q, const unsigned int a) const
    {
      return shape_values[q * n_nodes + a];
    }

    /**
     * Component @p component of @p entries at the nodes of @p cell (for
     * Q1, its vertices), in the order of the scalar element's shape
     * functions.
     */
    void
    nodal_values(const cell_iterator &cell,
                 const double        *entries,
                 const unsigned int   component,
                 ArrayView<double>  &&values) const;

    /**
     * The positions in the local entries of the displacement's dim
     * components at every node of the locally owned cells, each node once:
     * dim positions per node, in the order the cells first reach the
     * nodes. For passes over the nodes (the largest |u|), which over the
     * cells would visit a node once for each of its cells.
     */
    const std::vector<unsigned int> &
    displacement_node_positions() const
    {
      return node_positions;
    }

    /**
     * cell_vector(i) -= sum_q tau_q : eps(phi_i) over the displacement
     * shape functions phi_i of @p cell, for @p weighted_stress tau_q
     * already multiplied by JxW at each point.
     */
    void
    subtract_stress_work(
      const cell_iterator                           &cell,
      const ArrayView<const SymmetricTensor<2, dim>> weighted_stress,
      Vector<double>                                &cell_vector) const;

    /**
     * The gradients of the scalar shape functions at the points of @p cell:
     * grad N_a(x_q) at q * nodes_per_cell() + a (for the passes that need
     * several fields of a cell at once, from its nodal_values()).
     */
    const Tensor<1, dim> *
    shape_gradients(const cell_iterator &cell) const
    {
      return cell_gradients(cell->active_cell_index());
    }

    /// The number of distinct blocks of shape gradients stored: one for
    /// each shape of cell (one for all cells of a box).
    unsigned int
    n_gradient_blocks() const
    {
      return gradients.size() / (std::size_t(n_q_points) * n_nodes);
    }

    /// Quadrature point @p q of @p cell in real space.
    const Point<dim> &
    point(const cell_iterator &cell, const unsigned int q) const
    {
      return points[cell->active_cell_index() * n_q_points + q];
    }

  private:
    /// The most scalar shape functions per cell (Q2 in 3D).
    static constexpr unsigned int max_nodes = 27;

    /// A copy of the scalar element.
    std::unique_ptr<FiniteElement<dim>> scalar;
    /// The number of quadrature points and of scalar shape functions.
    unsigned int n_q_points = 0;
    unsigned int n_nodes    = 0;

    /// The number of degrees of freedom of a cell (of the FESystem).
    unsigned int dofs_per_cell = 0;

    /// The FESystem's shape function i is node node_of[i] of component
    /// component_of[i].
    std::vector<unsigned int> node_of;
    std::vector<unsigned int> component_of;

    /// The number of components, and whether shape function i is node
    /// i / n_components, component i % n_components: then the passes run
    /// the kernels of fixed_size_cell_kernels.h where the sizes are those
    /// of Q1 or P1.
    unsigned int n_components = 0;
    bool         node_major   = false;

    /// The values of the scalar shape functions at the points, the same on
    /// every cell: N_a(x_q) at q * n_nodes + a.
    std::vector<double> shape_values;

    /// The distinct blocks of shape gradients, grad N_a(x_q) at
    /// q * n_nodes + a in each, and for each cell (by active_cell_index) the
    /// index of its block: cells of the same shape share one (see
    /// GradientBlocks in cell_kinematics.cc).
    std::vector<Tensor<1, dim>> gradients;
    std::vector<unsigned int>   gradient_block;
    /// Per cell (at active_cell_index times the size of one cell's data):
    /// the points x_q, and the positions of the cell's entries in the
    /// ghosted layout.
    std::vector<Point<dim>>   points;
    std::vector<unsigned int> positions;
    /// See displacement_node_positions().
    std::vector<unsigned int> node_positions;

    /// Fill points, gradients, gradient_block and positions for the
    /// locally owned cells of @p dof_handler at the points of
    /// @p quadrature.
    void
    store_cells(const DoFHandler<dim> &dof_handler,
                const Quadrature<dim> &quadrature);

    /// Fill node_positions from the positions of the cells.
    void
    collect_displacement_nodes(const DoFHandler<dim> &dof_handler);

    /// The gradients of cell @p c (its active_cell_index).
    const Tensor<1, dim> *
    cell_gradients(const unsigned int c) const
    {
      return &gradients[std::size_t(gradient_block[c]) * n_q_points * n_nodes];
    }

    /// The layout the positions refer to, and copies of the layouts of the
    /// vectors found equal to it (see local_entries()).
    std::unique_ptr<Epetra_BlockMap>     layout;
    mutable std::vector<Epetra_BlockMap> equal_layouts;
  };
} // namespace VPContact

#endif
