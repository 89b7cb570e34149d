// The state stored at every quadrature point: the stress history of the
// paper's scheme, which lives in a piecewise discontinuous space.
#ifndef vpcontact_quadrature_history_h
#define vpcontact_quadrature_history_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * What the scheme keeps at one quadrature point between steps (as
   * step-18's PointHistory). The stress sigma_n is the paper's discrete
   * stress; the predictor sigma_{n-1} + k G_{n-1} is computed once per step
   * during the assembly of the right-hand side and reused by the stress
   * update, so that G is evaluated once per point and step. The damage
   * source phi_{n-1}, evaluated there too with the same state of step n-1,
   * is kept beside the points by StressHistory (damage_sources()).
   */
  template <int dim>
  struct QuadraturePointHistory
  {
    SymmetricTensor<2, dim> stress;
    SymmetricTensor<2, dim> predictor;
    /// The number of doubles that write_to() and read_from() use: the
    /// members, G_0, the viscoplastic rate of the initial state, and the
    /// damage source phi_{n-1}, both of which StressHistory keeps beside
    /// the points (initial_rates(), damage_sources()); a checkpoint stores
    /// this many per quadrature point. A new member must be added to all
    /// three.
    static constexpr unsigned int n_values
      = 3 * SymmetricTensor<2, dim>::n_independent_components + 1;

    /// Copy every member, @p initial_rate and @p damage_source into
    /// @p values (n_values of them), for checkpoints.
    void
    write_to(double                        *values,
             const SymmetricTensor<2, dim> &initial_rate,
             const double                   damage_source) const
    {
      for (unsigned int c = 0;
           c < SymmetricTensor<2, dim>::n_independent_components;
           ++c)
        {
          *values++ = stress.access_raw_entry(c);
          *values++ = predictor.access_raw_entry(c);
          *values++ = initial_rate.access_raw_entry(c);
        }
      *values = damage_source;
    }

    /// The inverse of write_to().
    void
    read_from(const double            *values,
              SymmetricTensor<2, dim> &initial_rate,
              double                  &damage_source)
    {
      for (unsigned int c = 0;
           c < SymmetricTensor<2, dim>::n_independent_components;
           ++c)
        {
          stress.access_raw_entry(c)       = *values++;
          predictor.access_raw_entry(c)    = *values++;
          initial_rate.access_raw_entry(c) = *values++;
        }
      damage_source = *values;
    }
  };

  /**
   * QuadraturePointHistory on the locally owned cells, the same number of
   * points on each: one flat array indexed by the cell's active_cell_index.
   * (deal.II's CellDataStorage does this job too, but looks a cell up in a
   * std::map and hands out a vector of shared pointers on every call, a
   * cost that a run visiting every cell several times per step pays each
   * time.) Valid until the mesh changes; clear() and initialize() set
   * it up again on the new mesh.
   *
   * Beside the points it keeps G_0, the viscoplastic rate of the initial
   * state, to which the time part of the error estimate refers
   * (ErrorEstimator): only the estimate reads it, and the passes of every
   * step over the points (right-hand side, stress update, damage load)
   * then stream 48 bytes per point in 2D rather than 80. A body that
   * starts at rest under the paper's law has G_0 = 0 at every point; then
   * release_zero_initial_rates() gives the array back (24 bytes a point in
   * 2D, 48 in 3D) and initial_rates() reads zeros. A new mesh starts so:
   * whoever writes G_0 (the estimate of step 0, a checkpoint or a mesh
   * transfer read back) calls keep_initial_rates() first.
   *
   * The damage source phi_{n-1} of every point is kept in an array of its
   * own (damage_sources()): the assembly of the right-hand side writes it,
   * and the damage load, the only pass that reads it, then streams 8 bytes
   * per point rather than the whole point.
   *
   * It also keeps the JxW of every point, given once per mesh by
   * set_JxW(): the passes that only integrate what is stored here (cell
   * stresses, elastic energy, damage statistics) then need no FEValues,
   * whose reinit() recomputes the mapping on every cell in every step.
   */
  template <int dim>
  class StressHistory
  {
  public:
    using cell_iterator = typename Triangulation<dim>::cell_iterator;

    void
    clear()
    {
      data.clear();
      rates.clear();
      zero_rates.clear();
      sources.clear();
      weights.clear();
      initialized.clear();
      n_points = 0;
    }

    /// Give @p cell (locally owned, active) @p n_q_points default points.
    void
    initialize(const cell_iterator &cell, const unsigned int n_q_points)
    {
      AssertThrow(n_points == 0 || n_points == n_q_points,
                  ExcMessage("Every cell has the same quadrature rule."));
      if (n_points == 0)
        {
          n_points = n_q_points;
          data.resize(cell->get_triangulation().n_active_cells() * n_points);
          // G_0 reads zero until keep_initial_rates() gives it an array:
          // the estimate of step 0 does, after the linear solver's set-up
          // (whose peak of memory it would otherwise add to).
          zero_rates.assign(n_points, SymmetricTensor<2, dim>());
          sources.assign(data.size(), 0.);
          weights.assign(data.size(), 0.);
          initialized.assign(cell->get_triangulation().n_active_cells(), false);
        }
      const unsigned int c = cell->active_cell_index();
      std::fill(data.begin() + c * n_points,
                data.begin() + (c + 1) * n_points,
                QuadraturePointHistory<dim>());
      if (!rates.empty())
        std::fill(rates.begin() + c * n_points,
                  rates.begin() + (c + 1) * n_points,
                  SymmetricTensor<2, dim>());
      std::fill(sources.begin() + c * n_points,
                sources.begin() + (c + 1) * n_points,
                0.);
      initialized[c] = true;
    }

    ArrayView<QuadraturePointHistory<dim>>
    get_data(const cell_iterator &cell)
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      return {data.data() + cell->active_cell_index() * n_points, n_points};
    }

    ArrayView<const QuadraturePointHistory<dim>>
    get_data(const cell_iterator &cell) const
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      return {data.data() + cell->active_cell_index() * n_points, n_points};
    }

    /// G_0 at the points of @p cell (see the class documentation), to be
    /// written: keep_initial_rates() first.
    ArrayView<SymmetricTensor<2, dim>>
    initial_rates(const cell_iterator &cell)
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      AssertThrow(zero_rates.empty(),
                  ExcMessage("keep_initial_rates() before writing G_0."));
      return {rates.data() + cell->active_cell_index() * n_points, n_points};
    }

    ArrayView<const SymmetricTensor<2, dim>>
    initial_rates(const cell_iterator &cell) const
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      if (!zero_rates.empty())
        return {zero_rates.data(), n_points};
      return {rates.data() + cell->active_cell_index() * n_points, n_points};
    }

    /// If G_0 is zero at every point, give its array back; initial_rates()
    /// then reads zeros. A pass over the points until the first rate that
    /// is not zero.
    void
    release_zero_initial_rates()
    {
      if (!zero_rates.empty() || n_points == 0)
        return;
      for (const auto &rate : rates)
        for (unsigned int c = 0;
             c < SymmetricTensor<2, dim>::n_independent_components;
             ++c)
          if (rate.access_raw_entry(c) != 0.)
            return;
      std::vector<SymmetricTensor<2, dim>>().swap(rates);
      zero_rates.assign(n_points, SymmetricTensor<2, dim>());
    }

    /// An array for G_0, zero at every point, where there is none (on a
    /// new mesh, or after release_zero_initial_rates()); otherwise nothing.
    void
    keep_initial_rates()
    {
      if (zero_rates.empty())
        return;
      rates.assign(data.size(), SymmetricTensor<2, dim>());
      zero_rates.clear();
    }

    /// phi_{n-1} at the points of @p cell (damage scenes).
    ArrayView<double>
    damage_sources(const cell_iterator &cell)
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      return {sources.data() + cell->active_cell_index() * n_points, n_points};
    }

    ArrayView<const double>
    damage_sources(const cell_iterator &cell) const
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      return {sources.data() + cell->active_cell_index() * n_points, n_points};
    }

    /// damage_sources() and JxW() of the cell with active cell index
    /// @p index, for the passes that run over a list of cells by index
    /// (DamageProblem's load) rather than over cell iterators.
    ArrayView<const double>
    damage_sources(const unsigned int index) const
    {
      Assert(initialized[index], ExcInternalError());
      return {sources.data() + index * n_points, n_points};
    }

    ArrayView<const double>
    JxW(const unsigned int index) const
    {
      Assert(initialized[index], ExcInternalError());
      return {weights.data() + index * n_points, n_points};
    }

    /// Store the JxW values @p JxW of the points of @p cell (initialized).
    void
    set_JxW(const cell_iterator &cell, const std::vector<double> &JxW)
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      AssertDimension(JxW.size(), n_points);
      std::copy(JxW.begin(),
                JxW.end(),
                weights.begin() + cell->active_cell_index() * n_points);
    }

    /// The JxW values of the points of @p cell, as given to set_JxW().
    ArrayView<const double>
    JxW(const cell_iterator &cell) const
    {
      Assert(initialized[cell->active_cell_index()], ExcInternalError());
      return {weights.data() + cell->active_cell_index() * n_points, n_points};
    }

  private:
    std::vector<QuadraturePointHistory<dim>> data;
    std::vector<SymmetricTensor<2, dim>>     rates;
    /// One cell's zero rates, which initial_rates() reads once rates is
    /// given back (empty while rates holds G_0).
    std::vector<SymmetricTensor<2, dim>> zero_rates;
    std::vector<double>                  sources;
    std::vector<double>                  weights;
    std::vector<bool>                    initialized;
    unsigned int                         n_points = 0;
  };
} // namespace VPContact

#endif
