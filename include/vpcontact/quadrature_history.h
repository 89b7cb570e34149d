// The state stored at every quadrature point: the stress history of the
// paper's scheme, which lives in a piecewise discontinuous space.
#ifndef vpcontact_quadrature_history_h
#define vpcontact_quadrature_history_h

#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/grid/tria.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * What the scheme keeps at one quadrature point between steps (as
   * step-18's PointHistory). The stress sigma_n is the paper's discrete
   * stress; the predictor sigma_{n-1} + k G_{n-1} is computed once per step
   * during the assembly of the right-hand side and reused by the stress
   * update, so that G is evaluated once per point and step; the damage
   * source phi_{n-1} is evaluated there too, with the same state of step
   * n-1, and used by the damage step.
   */
  template <int dim>
  struct QuadraturePointHistory
  {
    SymmetricTensor<2, dim> stress;
    SymmetricTensor<2, dim> predictor;
    /// phi_{n-1}, the damage source of the current step (damage scenes).
    double damage_source = 0;

    /// The number of doubles that write_to() and read_from() use; a
    /// checkpoint stores this many per quadrature point. A new member must
    /// be added to all three.
    static constexpr unsigned int n_values
      = 2 * SymmetricTensor<2, dim>::n_independent_components + 1;

    /// Copy every member into @p values (n_values of them), for checkpoints.
    void
    write_to(double *values) const
    {
      for (unsigned int c = 0;
           c < SymmetricTensor<2, dim>::n_independent_components;
           ++c)
        {
          *values++ = stress.access_raw_entry(c);
          *values++ = predictor.access_raw_entry(c);
        }
      *values = damage_source;
    }

    /// The inverse of write_to().
    void
    read_from(const double *values)
    {
      for (unsigned int c = 0;
           c < SymmetricTensor<2, dim>::n_independent_components;
           ++c)
        {
          stress.access_raw_entry(c)    = *values++;
          predictor.access_raw_entry(c) = *values++;
        }
      damage_source = *values;
    }
  };

  /// The per-cell storage of QuadraturePointHistory (deal.II's
  /// CellDataStorage, on the locally owned cells).
  template <int dim>
  using StressHistory
    = CellDataStorage<typename Triangulation<dim>::cell_iterator,
                      QuadraturePointHistory<dim>>;
} // namespace VPContact

#endif
