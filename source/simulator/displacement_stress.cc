// The displacement problem's stress: the update sigma_n = sigma_{n-1} + k
// G_{n-1} + E eps(du) at every quadrature point, its safeguards, and the
// quantities derived from it for output.
#include <vpcontact/app/exit_agreement.h>
#include <vpcontact/fe/owned_constraints.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/material/stress_measures.h>
#include <vpcontact/simulator/displacement_problem.h>

#include <deal.II/base/parallel.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace VPContact
{
  namespace
  {
    /// The cell average of the quadrature point stress, from the points of
    /// a cell (@p history) and their weights @p JxW: its L2 projection on
    /// piecewise constants, the paper's P_Q (exact for the stress of a
    /// parallelogram cell, which is constant).
    template <typename History, typename Weights>
    auto
    cell_average_stress(const History &history, const Weights &JxW)
    {
      std::decay_t<decltype(history[0].stress)> average; // zero
      double                                    volume = 0;
      for (unsigned int q = 0; q < history.size(); ++q)
        {
          average += history[q].stress * JxW[q];
          volume += JxW[q];
        }
      return average / volume;
    }
  } // namespace



  template <int dim>
  double
  DisplacementProblem<dim>::update_stress_chunk(
    const unsigned int  c,
    const double *const increment_entries,
    const double *const solution_entries)
  {
    // sigma_n = sigma_{n-1} + k G_{n-1} + E eps(du) (the predictor with
    // the increment), or, with @p solution_entries, the backward Euler
    // update, at the points of the cells of chunk c. NaN compares false
    // and is turned into infinity.
    const bool implicit = (solution_entries != nullptr);
    std::vector<SymmetricTensor<2, dim>> strain_increments(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    std::vector<double>                  damage_values(quadrature.size(), 1.);
    double                               largest = 0;
    const std::size_t first = owned_cells.size() * c / stress_chunks;
    const std::size_t last  = owned_cells.size() * (c + 1) / stress_chunks;
    for (std::size_t i = first; i < last; ++i)
      {
        const auto &cell = owned_cells[i];
        cell_kinematics.strains(cell,
                                increment_entries,
                                make_array_view(strain_increments));
        if (implicit)
          {
            cell_kinematics.strains(cell,
                                    solution_entries,
                                    make_array_view(strains));
            if (damage_model.is_active())
              cell_kinematics.damage(cell,
                                     solution_entries,
                                     make_array_view(damage_values));
          }
        const auto history = stress_history.get_data(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            auto &point = history[q];
            if (implicit)
              point.stress
                = implicit_stress_update(
                    *viscoplastic_law,
                    point.stress + material.stress(strain_increments[q]),
                    strains[q],
                    damage_values[q],
                    time_discretization.step_size(),
                    material.stiffness())
                    .stress;
            else
              point.stress
                = point.predictor + material.stress(strain_increments[q]);
            for (unsigned int i = 0;
                 i < SymmetricTensor<2, dim>::n_independent_components;
                 ++i)
              {
                const double value = std::abs(point.stress.access_raw_entry(i));
                largest            = (value >= largest ?
                                        value :
                                      std::isnan(value) ?
                                        std::numeric_limits<double>::infinity() :
                                        largest);
              }
          }
      }
    return largest;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::update_stress_ahead(
    const double *const increment_entries)
  {
    // Runs in the second thread after the substitutions, on one rank (the
    // factors solve in the background only there): no MPI function. On one
    // rank the constraints read only owned entries, and the ghosted
    // increment has the layout of the owned one. A later active-set
    // iteration solves again and starts the pass over (stress_ahead is
    // restarted); the predictor it reads is not touched here.
    AssertThrow(!increment.has_ghost_elements()
                  && increment.locally_owned_size()
                       == increment_owned.locally_owned_size(),
                ExcInternalError());
    distribute_owned_constraints(constraints, increment_owned.block(0));
    double *entry = increment.begin();
    for (unsigned int b = 0; b < increment_owned.n_blocks(); ++b)
      entry = std::copy(increment_owned.block(b).begin(),
                        increment_owned.block(b).end(),
                        entry);
    stress_chunk_largest.resize(stress_chunks);
    stress_ahead.run_ahead(stress_chunks,
                           [this, increment_entries](const unsigned int c) {
                             stress_chunk_largest[c]
                               = update_stress_chunk(c, increment_entries);
                           });
  }



  template <int dim>
  void
  DisplacementProblem<dim>::update_stress(const unsigned int n)
  {
    TimerOutput::Scope t(computing_timer, "Stress update");

    // Backward Euler solves for the stress again from sigma_{n-1}, with the
    // strain of u_n and the damage zeta_{n-1} (still in the solution).
    // The chunks the second thread did ahead (see update_stress_ahead())
    // are done; the others run in the threads deal.II has (TBB). Each
    // writes only the quadrature points of its cells and returns its
    // largest stress component, to catch an explicit step that has blown
    // up.
    const bool          implicit = viscoplasticity.implicit() && n > 0;
    const double *const increment_entries
      = cell_kinematics.local_entries(increment);
    const double *const solution_entries
      = implicit ? cell_kinematics.local_entries(solution) : nullptr;
    const unsigned int first = stress_ahead.take_done();
    stress_chunk_largest.resize(stress_chunks);
    // The local Newton solve of the backward Euler update may fail at a
    // point of one rank's cells only: all ranks stop together.
    stop_together(mpi_communicator, [&]() {
      parallel::apply_to_subranges(
        first,
        stress_chunks,
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int c = begin; c < end; ++c)
            stress_chunk_largest[c]
              = update_stress_chunk(c, increment_entries, solution_entries);
        },
        1);
    });
    double largest = *std::max_element(stress_chunk_largest.begin(),
                                       stress_chunk_largest.end());
    largest        = Utilities::MPI::max(largest, mpi_communicator);

    const double limit
      = viscoplasticity.divergence_limit() * material.youngs_modulus();
    AssertThrow(std::isfinite(largest) && largest <= limit,
                ExcMessage(
                  "Step " + std::to_string(n) + " (t = "
                  + to_text(time_discretization.time(n)) + "): the stress "
                  + (std::isfinite(largest) ?
                       "reached " + to_text(largest) + " Pa, more than "
                         + "Viscoplasticity/Divergence limit x E = "
                         + to_text(limit) + " Pa" :
                       "is not finite (NaN or Inf)")
                  + ". The explicit viscoplastic step (law: "
                  + viscoplastic_law->description()
                  + ") is probably unstable: reduce Time/Time step = "
                  + to_text(time_discretization.step_size())
                  + ", or check the loads. The output up to step "
                  + std::to_string(n == 0 ? 0 : n - 1) + " is complete in "
                  + output_writer.directory() + "."));
  }



  template <int dim>
  void
  DisplacementProblem<dim>::compute_cell_stresses(
    Vector<double>              &von_mises,
    std::vector<Vector<double>> &components) const
  {
    // The cell average of the quadrature point stress (see
    // cell_average_stress()).
    von_mises.reinit(triangulation.n_active_cells());
    components.assign(SymmetricTensor<2, dim>::n_independent_components,
                      Vector<double>(triangulation.n_active_cells()));
    // Each cell writes its own entries.
    parallel::apply_to_subranges(
      std::size_t(0),
      owned_cells.size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          {
            const auto                   &cell = owned_cells[i];
            const SymmetricTensor<2, dim> average
              = cell_average_stress(stress_history.get_data(cell),
                                    stress_history.JxW(cell));
            const unsigned int index = cell->active_cell_index();
            von_mises(index)         = von_mises_norm(average);
            for (unsigned int c = 0; c < components.size(); ++c)
              components[c](index) = average.access_raw_entry(c);
          }
      },
      64);
  }



  template <int dim>
  StepMeasures
  DisplacementProblem<dim>::measure_step() const
  {
    // One pass over the cells for what every step reports (see
    // measure_chunk()). The sums run over chunks of the cells in the
    // threads, and the chunks are added in their order: the same bits with
    // any number of threads.
    const double *const   entries = cell_kinematics.local_entries(solution);
    std::vector<StepSums> chunk_sums(stress_chunks);
    parallel::apply_to_subranges(
      0u,
      stress_chunks,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int c = begin; c < end; ++c)
          measure_chunk(c, entries, chunk_sums[c]);
      },
      1);
    StepSums sums;
    for (const StepSums &chunk : chunk_sums)
      {
        sums.von_mises_max = std::max(sums.von_mises_max, chunk.von_mises_max);
        sums.u_square_max  = std::max(sums.u_square_max, chunk.u_square_max);
        sums.energy += chunk.energy;
        sums.damaged += chunk.damaged;
        sums.volume += chunk.volume;
        sums.u_finite    = sums.u_finite && chunk.u_finite;
        sums.zeta_finite = sums.zeta_finite && chunk.zeta_finite;
      }

    StepMeasures measures;
    measures.von_mises_max
      = Utilities::MPI::max(sums.von_mises_max, mpi_communicator);
    measures.u_max
      = Utilities::MPI::max(std::sqrt(sums.u_square_max), mpi_communicator);
    measures.energy = Utilities::MPI::sum(sums.energy, mpi_communicator);
    measures.u_finite
      = !Utilities::MPI::logical_or(!sums.u_finite, mpi_communicator);
    measures.zeta_finite
      = !Utilities::MPI::logical_or(!sums.zeta_finite, mpi_communicator);
    if (damage_model.is_active())
      measures.damaged_fraction
        = Utilities::MPI::sum(sums.damaged, mpi_communicator)
          / Utilities::MPI::sum(sums.volume, mpi_communicator);
    return measures;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::measure_chunk(const unsigned int  c,
                                          const double *const entries,
                                          StepSums           &sums) const
  {
    // On the cells of chunk @p c:
    // - the largest von Mises stress of the cell averages of sigma (the
    //   paper's P_Q sigma, as in the fields);
    // - the largest nodal |u|, over the nodes of the locally owned cells,
    //   read through CellKinematics' positions;
    // - the energy stored in the stress, 1/2 (E^{-1} sigma, sigma): for an
    //   elastic body 1/2 (E eps(u), eps(u)), lowered by viscous relaxation;
    // - with damage, the volume where zeta < 1 at the quadrature points.
    const SymmetricTensor<4, dim> &compliance = material.compliance();
    const unsigned int             n_nodes = cell_kinematics.nodes_per_cell();
    std::vector<double>            norm_square(n_nodes), component(n_nodes),
      zeta(quadrature.size());
    for (std::size_t i = owned_cells.size() * c / stress_chunks;
         i < owned_cells.size() * (c + 1) / stress_chunks;
         ++i)
      {
        const auto &cell    = owned_cells[i];
        const auto  history = stress_history.get_data(cell);
        const auto  JxW     = stress_history.JxW(cell);
        for (unsigned int q = 0; q < history.size(); ++q)
          sums.energy += 0.5 * (compliance * history[q].stress)
                         * history[q].stress * JxW[q];
        sums.von_mises_max
          = std::max(sums.von_mises_max,
                     von_mises_norm(cell_average_stress(history, JxW)));

        std::fill(norm_square.begin(), norm_square.end(), 0.);
        for (unsigned int d = 0; d < dim; ++d)
          {
            cell_kinematics.nodal_values(cell,
                                         entries,
                                         d,
                                         make_array_view(component));
            for (unsigned int a = 0; a < n_nodes; ++a)
              norm_square[a] += component[a] * component[a];
          }
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            sums.u_square_max = std::max(sums.u_square_max, norm_square[a]);
            sums.u_finite     = sums.u_finite && std::isfinite(norm_square[a]);
          }

        if (damage_model.is_active())
          {
            cell_kinematics.damage(cell, entries, make_array_view(zeta));
            for (unsigned int q = 0; q < JxW.size(); ++q)
              {
                sums.volume += JxW[q];
                sums.zeta_finite = sums.zeta_finite && std::isfinite(zeta[q]);
                if (zeta[q] < 1. - 1e-12)
                  sums.damaged += JxW[q];
              }
          }
      }
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
