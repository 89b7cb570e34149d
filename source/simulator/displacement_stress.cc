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



    /// The larger of @p largest and the largest |component| of @p stress.
    /// NaN compares false and is turned into infinity.
    template <int dim>
    double
    larger_component(const SymmetricTensor<2, dim> &stress, double largest)
    {
      for (unsigned int i = 0;
           i < SymmetricTensor<2, dim>::n_independent_components;
           ++i)
        {
          const double value = std::abs(stress.access_raw_entry(i));
          largest
            = (value >= largest  ? value :
               std::isnan(value) ? std::numeric_limits<double>::infinity() :
                                   largest);
        }
      return largest;
    }



    /// Adds the energy stored in the stress at the points of a cell,
    /// 1/2 (E^{-1} sigma, sigma) (for an elastic body 1/2 (E eps(u),
    /// eps(u)), lowered by viscous relaxation), and the von Mises stress of
    /// its cell average (the paper's P_Q sigma, as in the fields) to
    /// @p sums.
    template <int dim, typename History, typename Weights, typename Sums>
    void
    add_cell_stress_measures(const StressQuadraticForm<dim> &compliance,
                             const History                  &history,
                             const Weights                  &JxW,
                             Sums                           &sums)
    {
      for (unsigned int q = 0; q < history.size(); ++q)
        sums.energy += 0.5 * compliance(history[q].stress) * JxW[q];
      sums.von_mises_max
        = std::max(sums.von_mises_max,
                   von_mises_norm(cell_average_stress(history, JxW)));
    }
  } // namespace



  template <int dim>
  typename DisplacementProblem<dim>::StressSums
  DisplacementProblem<dim>::update_stress_chunk(
    const unsigned int  c,
    const double *const increment_entries,
    const double *const solution_entries)
  {
    // sigma_n = sigma_{n-1} + k G_{n-1} + E eps(du) (the predictor with
    // the increment), or, with @p solution_entries, the backward Euler
    // update, at the points of the cells of chunk c.
    const bool implicit = (solution_entries != nullptr);
    std::vector<SymmetricTensor<2, dim>> strain_increments(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    std::vector<double>                  damage_values(quadrature.size(), 1.);
    StressSums                           sums;
    const StressQuadraticForm<dim>       compliance(material.compliance());
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
            sums.largest = larger_component(point.stress, sums.largest);
          }
        // The measures of the step, while the points are in the cache.
        add_cell_stress_measures(compliance,
                                 history,
                                 stress_history.JxW(cell),
                                 sums);
      }
    return sums;
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
    stress_chunk_sums.resize(stress_chunks);
    stress_ahead.run_ahead(stress_chunks,
                           [this, increment_entries](const unsigned int c) {
                             stress_chunk_sums[c]
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
    stress_chunk_sums.resize(stress_chunks);
    // The local Newton solve of the backward Euler update may fail at a
    // point of one rank's cells only: all ranks stop together.
    stop_together(mpi_communicator, [&]() {
      parallel::apply_to_subranges(
        first,
        stress_chunks,
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int c = begin; c < end; ++c)
            stress_chunk_sums[c]
              = update_stress_chunk(c, increment_entries, solution_entries);
        },
        1);
    });
    stress_sums_current = true;
    double largest      = 0;
    for (const StressSums &sums : stress_chunk_sums)
      largest = std::max(largest, sums.largest);
    largest = Utilities::MPI::max(largest, mpi_communicator);

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
    // What every step reports of its state. The stress update leaves the
    // stress' sums of each chunk of the cells (update_stress_chunk()); they
    // are measured here only where the points changed otherwise (the
    // initial state, a new mesh, a checkpoint). The sums of the chunks are
    // added in their order: the same bits with any number of threads, and
    // whichever pass made them.
    std::vector<StressSums> stress_sums = stress_chunk_sums;
    if (!stress_sums_current)
      {
        stress_sums.resize(stress_chunks);
        parallel::apply_to_subranges(
          0u,
          stress_chunks,
          [&](const unsigned int begin, const unsigned int end) {
            for (unsigned int c = begin; c < end; ++c)
              stress_sums[c] = measure_stress_chunk(c);
          },
          1);
      }
    const double *const     entries = cell_kinematics.local_entries(solution);
    std::vector<DamageSums> damage_sums(stress_chunks);
    if (damage_model.is_active())
      parallel::apply_to_subranges(
        0u,
        stress_chunks,
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int c = begin; c < end; ++c)
            damage_sums[c] = measure_damage_chunk(c, entries);
        },
        1);

    StressSums stress;
    DamageSums damage;
    for (unsigned int c = 0; c < stress_chunks; ++c)
      {
        stress.energy += stress_sums[c].energy;
        stress.von_mises_max
          = std::max(stress.von_mises_max, stress_sums[c].von_mises_max);
        damage.damaged += damage_sums[c].damaged;
        damage.volume += damage_sums[c].volume;
        damage.zeta_finite = damage.zeta_finite && damage_sums[c].zeta_finite;
      }
    StepMeasures measures;
    measures.von_mises_max
      = Utilities::MPI::max(stress.von_mises_max, mpi_communicator);
    measures.energy = Utilities::MPI::sum(stress.energy, mpi_communicator);
    measure_displacement(entries, measures);
    measures.zeta_finite
      = !Utilities::MPI::logical_or(!damage.zeta_finite, mpi_communicator);
    if (damage_model.is_active())
      measures.damaged_fraction
        = Utilities::MPI::sum(damage.damaged, mpi_communicator)
          / Utilities::MPI::sum(damage.volume, mpi_communicator);
    return measures;
  }



  template <int dim>
  void
  DisplacementProblem<dim>::measure_displacement(const double *const entries,
                                                 StepMeasures &measures) const
  {
    // The largest nodal |u| over the nodes of the locally owned cells,
    // each node once (std::max() passes NaN by: it is counted apart).
    const std::vector<unsigned int> &nodes
      = cell_kinematics.displacement_node_positions();
    double u_square_max = 0;
    bool   u_finite     = true;
    for (std::size_t i = 0; i < nodes.size(); i += dim)
      {
        double norm_square = 0;
        for (unsigned int d = 0; d < dim; ++d)
          norm_square += entries[nodes[i + d]] * entries[nodes[i + d]];
        u_square_max = std::max(u_square_max, norm_square);
        u_finite     = u_finite && std::isfinite(norm_square);
      }
    measures.u_max
      = Utilities::MPI::max(std::sqrt(u_square_max), mpi_communicator);
    measures.u_finite
      = !Utilities::MPI::logical_or(!u_finite, mpi_communicator);
  }



  template <int dim>
  typename DisplacementProblem<dim>::StressSums
  DisplacementProblem<dim>::measure_stress_chunk(const unsigned int c) const
  {
    StressSums                     sums;
    const StressQuadraticForm<dim> compliance(material.compliance());
    for (std::size_t i = owned_cells.size() * c / stress_chunks;
         i < owned_cells.size() * (c + 1) / stress_chunks;
         ++i)
      add_cell_stress_measures(compliance,
                               stress_history.get_data(owned_cells[i]),
                               stress_history.JxW(owned_cells[i]),
                               sums);
    return sums;
  }



  template <int dim>
  typename DisplacementProblem<dim>::DamageSums
  DisplacementProblem<dim>::measure_damage_chunk(
    const unsigned int  c,
    const double *const entries) const
  {
    // The volume where zeta < 1 at the quadrature points.
    std::vector<double> zeta(quadrature.size());
    DamageSums          sums;
    for (std::size_t i = owned_cells.size() * c / stress_chunks;
         i < owned_cells.size() * (c + 1) / stress_chunks;
         ++i)
      {
        const auto &cell = owned_cells[i];
        const auto  JxW  = stress_history.JxW(cell);
        cell_kinematics.damage(cell, entries, make_array_view(zeta));
        for (unsigned int q = 0; q < JxW.size(); ++q)
          {
            sums.volume += JxW[q];
            sums.zeta_finite = sums.zeta_finite && std::isfinite(zeta[q]);
            if (zeta[q] < 1. - 1e-12)
              sums.damaged += JxW[q];
          }
      }
    return sums;
  }



  template class DisplacementProblem<2>;
  template class DisplacementProblem<3>;
} // namespace VPContact
