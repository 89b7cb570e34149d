// The loops of CellKinematics over one cell with the number of nodes and of
// components known at compile time, for the elements every scene uses (Q1
// and P1, with or without the damage component).
#ifndef vpcontact_fixed_size_cell_kernels_h
#define vpcontact_fixed_size_cell_kernels_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <type_traits>

namespace VPContact
{
  namespace FixedSizeCellKernels
  {
    using namespace dealii;

    // Why: the general loops of CellKinematics run over the FESystem's
    // shape functions with a branch on each one's component and read each
    // entry of the vector once per quadrature point, since the compiler
    // cannot know that the output does not alias the entries. With the
    // sizes fixed, the cell's entries are read once into registers and the
    // loops unroll. Every sum runs in the order of the general loops (node
    // by node), so the results are the same bits.
    //
    // Shape function i of a cell is node i / n_components, component
    // i % n_components (the FESystem's order for these elements, checked
    // by CellKinematics::reinit()).

    /// The strains at the @p n_q points of a cell with entries at
    /// positions @p dofs and gradients @p grad (q * n_nodes + a).
    template <int dim, int n_nodes, int n_components>
    inline void
    strains(const unsigned int      *dofs,
            const double            *entries,
            const Tensor<1, dim>    *grad,
            const unsigned int       n_q,
            SymmetricTensor<2, dim> *out)
    {
      double u[n_nodes][dim];
      for (int a = 0; a < n_nodes; ++a)
        for (int d = 0; d < dim; ++d)
          u[a][d] = entries[dofs[a * n_components + d]];
      for (unsigned int q = 0; q < n_q; ++q)
        {
          const Tensor<1, dim> *g = grad + q * n_nodes;
          Tensor<2, dim>        du;
          for (int a = 0; a < n_nodes; ++a)
            for (int d = 0; d < dim; ++d)
              for (int e = 0; e < dim; ++e)
                du[d][e] += u[a][d] * g[a][e];
          out[q] = symmetrize(du);
        }
    }

    /// The damage (component dim) at the @p n_q points, from the values
    /// @p shape_values (q * n_nodes + a) of the scalar shape functions.
    template <int dim, int n_nodes, int n_components>
    inline void
    damage(const unsigned int *dofs,
           const double       *entries,
           const double       *shape_values,
           const unsigned int  n_q,
           double             *out)
    {
      static_assert(n_components == dim + 1, "no damage component");
      double z[n_nodes];
      for (int a = 0; a < n_nodes; ++a)
        z[a] = entries[dofs[a * n_components + dim]];
      for (unsigned int q = 0; q < n_q; ++q)
        {
          double value = 0;
          for (int a = 0; a < n_nodes; ++a)
            value += z[a] * shape_values[q * n_nodes + a];
          out[q] = value;
        }
    }

    /// cell_vector(i) -= sum_q tau_q : eps(phi_i) for the displacement's
    /// shape functions phi_i, with @p tau already weighted by JxW.
    template <int dim, int n_nodes, int n_components>
    inline void
    subtract_stress_work(const Tensor<1, dim>          *grad,
                         const SymmetricTensor<2, dim> *tau,
                         const unsigned int             n_q,
                         double                        *cell_vector)
    {
      for (unsigned int q = 0; q < n_q; ++q)
        for (int a = 0; a < n_nodes; ++a)
          {
            const Tensor<1, dim> traction = tau[q] * grad[q * n_nodes + a];
            for (int d = 0; d < dim; ++d)
              cell_vector[a * n_components + d] -= traction[d];
          }
    }

    /**
     * Call @p kernel(nodes, components), with both as
     * std::integral_constant, for the sizes of Q1 and P1 with dim or
     * dim + 1 components; false for any other size (the caller then runs
     * its general loop).
     */
    template <int dim, typename Kernel>
    inline bool
    with_fixed_sizes(const unsigned int n_nodes,
                     const unsigned int n_components,
                     Kernel           &&kernel)
    {
      using Q1               = std::integral_constant<int, (1 << dim)>;
      using P1               = std::integral_constant<int, dim + 1>;
      using Plain            = std::integral_constant<int, dim>;
      using WithDamage       = std::integral_constant<int, dim + 1>;
      const bool with_damage = (n_components == dim + 1);
      if (n_components != dim && !with_damage)
        return false;
      if (n_nodes == Q1::value)
        with_damage ? kernel(Q1(), WithDamage()) : kernel(Q1(), Plain());
      else if (n_nodes == P1::value)
        with_damage ? kernel(P1(), WithDamage()) : kernel(P1(), Plain());
      else
        return false;
      return true;
    }
  } // namespace FixedSizeCellKernels
} // namespace VPContact

#endif
