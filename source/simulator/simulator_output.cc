// The simulator's output: cell-averaged stresses, the statistics row of every
// step, the screen, and the fields for ParaView.
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/material/stress_measures.h>
#include <vpcontact/postprocess/piece_builder.h>
#include <vpcontact/simulator/simulator.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <cstdio>
#include <fstream>
#include <memory>
#include <utility>

namespace VPContact
{
  namespace
  {
    // Names of the independent stress components, in the order of
    // SymmetricTensor's unrolled index: xx, yy, (zz,) xy, (xz, yz).
    template <int dim>
    std::vector<std::string>
    stress_component_names()
    {
      if (dim == 2)
        return {"stress_xx", "stress_yy", "stress_xy"};
      return {"stress_xx",
              "stress_yy",
              "stress_zz",
              "stress_xy",
              "stress_xz",
              "stress_yz"};
    }

  } // namespace



  template <int dim>
  void
  Simulator<dim>::print_header() const
  {
    const unsigned int n_ranks
      = Utilities::MPI::n_mpi_processes(mpi_communicator);
    pcout << "vpcontact: " << dim << "D quasistatic viscoplastic body ("
          << (dim == 3 ? "3D" :
              displacement_problem.elastic_material().plane_hypothesis()
                  == ElasticMaterial<dim>::PlaneHypothesis::plane_stress ?
                         "plane stress" :
                         "plane strain")
          << "), E = "
          << displacement_problem.elastic_material().youngs_modulus()
          << ", nu = "
          << displacement_problem.elastic_material().poisson_ratio() << '\n'
          << "  viscoplastic law: " << displacement_problem.law().description()
          << '\n'
          << "  initial state: " << initial_conditions.description() << '\n'
          << "  damage: " << damage_model.description() << '\n'
          << "  boundary: " << displacement_problem.boundaries().summary()
          << '\n'
          << "  contact: " << displacement_problem.contact_description() << '\n'
          << "  mesh: " << mesh->n_global_active_cells() << " cells"
          << (discretization.simplex() ?
                " (" + discretization.description() + ")" :
                std::string())
          << ", " << dof_handler.n_dofs() << " dofs" << '\n'
          << (convergence_study.refinement().adapts_during_run() ?
                "  adapting the mesh: "
                  + convergence_study.refinement().run_description() + '\n' :
                std::string())
          << "  time: T = " << time_discretization.end_time()
          << ", k = " << time_discretization.step_size() << ", "
          << time_discretization.n_steps() << " steps\n";
    // The solver is named only where the output may differ between 1 and
    // several ranks: the automatic choice depends on the ranks.
    if (!output_writer.deterministic_screen_output())
      pcout << "  solver: " << displacement_problem.solver().description()
            << '\n'
            << "  running on " << n_ranks << " MPI rank(s); output in "
            << output_writer.directory() << "/\n";
    pcout << std::endl;
  }



  template <int dim>
  void
  Simulator<dim>::check_finite(const StepMeasures &measures,
                               const unsigned int  n) const
  {
    // The state of step n is checked before anything of it is written, so
    // that the output holds only finite steps.
    std::string quantity;
    if (!measures.u_finite)
      quantity = "the displacement u";
    else if (!std::isfinite(measures.energy))
      quantity = "the stress (its energy)";
    else if (!measures.zeta_finite)
      quantity = "the damage zeta";
    // A displacement far beyond the body's size is no longer small strain:
    // an unstable or unbounded step, stopped as the stress is (see
    // update_stress()).
    const double u_limit = displacement_problem.displacement_limit();
    AssertThrow(!quantity.empty() || measures.u_max <= u_limit,
                ExcMessage("Step " + std::to_string(n)
                           + " (t = " + to_text(time_discretization.time(n))
                           + "): the displacement reached "
                           + to_text(measures.u_max)
                           + " m, more than Viscoplasticity/Divergence limit "
                             "x the body's size = "
                           + to_text(u_limit)
                           + " m. The viscoplastic step is unstable or the "
                             "body is not held; check the law's data and "
                             "Time/Time step. The output up to the step "
                             "before is complete in "
                           + output_writer.directory() + "."));
    AssertThrow(
      quantity.empty(),
      ExcMessage(
        "Step " + std::to_string(n)
        + " (t = " + to_text(time_discretization.time(n)) + "): " + quantity
        + " is not finite (NaN or infinity). Inputs that can cause this: "
          "loads that are not finite somewhere (Boundary conditions/Traction, "
          "Body force, Prescribed displacement), a damage source that is not "
          "(Damage/Source), or material data whose products overflow "
          "(Material, Viscoplasticity). The output up to the step before "
          "is complete in "
        + output_writer.directory() + "."));
  }



  template <int dim>
  std::string
  Simulator<dim>::add_step_statistics(const unsigned int  n,
                                      const double        step_wall_time,
                                      const StepMeasures &measures)
  {
    // A new row of statistics.csv with what every scene reports, and the
    // start of the step's screen line.
    const double time = time_discretization.time(n);
    statistics.start_row();
    statistics.add_value("step", n);
    statistics.add_value("time", time);
    statistics.add_value("cells",
                         static_cast<unsigned long long>(
                           mesh->n_global_active_cells()));
    statistics.add_value("dofs",
                         static_cast<unsigned long long>(dof_handler.n_dofs()));
    statistics.add_value("linear_iterations",
                         displacement_problem.linear_iterations());
    statistics.add_value("wall_time", step_wall_time);
    statistics.add_value("u_max", measures.u_max);
    statistics.add_value("von_mises_max", measures.von_mises_max);
    statistics.add_value("elastic_energy", measures.energy);
    monitor_points.add_statistics(displacement_problem.ghosted_solution(),
                                  statistics);
    return "step " + std::to_string(n) + "  t = " + printf_text("%.6g", time)
           + "  |u|max = " + printf_text("%.6e", measures.u_max)
           + "  von Mises max = " + printf_text("%.6e", measures.von_mises_max)
           + "  energy = " + printf_text("%.6e", measures.energy);
  }



  template <int dim>
  void
  Simulator<dim>::collect_step_reports()
  {
    // The columns of the physics objects that report before the errors
    // (damage) come first, the others (friction) last, as in the tables of
    // earlier runs that users compare with.
    const auto add_physics_reports = [this](const bool before_errors) {
      for (Physics<dim> *object : physics)
        if (object->reports_before_errors() == before_errors)
          step_reports.push_back(
            [this, object](std::string &line, const StepReport &report) {
              object->add_statistics(statistics, line, report.quantities);
            });
    };
    step_reports.clear();
    add_physics_reports(true);
    step_reports.push_back([this](std::string &line, const StepReport &report) {
      add_verification_statistics(line,
                                  report.time,
                                  report.u_max,
                                  report.components);
    });
    step_reports.push_back([this](std::string &line, const StepReport &report) {
      const unsigned int n = report.n;
      convergence_study.add_reference_statistics(
        n,
        time_discretization,
        [this, n]() { return make_snapshot(time_discretization.time(n)); },
        statistics,
        line,
        mpi_communicator);
    });
    add_physics_reports(false);
  }



  template <int dim>
  void
  Simulator<dim>::postprocess_step(const unsigned int   n,
                                   const double         step_wall_time,
                                   const ErrorEstimate &estimate)
  {
    TimerOutput::Scope t(computing_timer, "Postprocess and output");
    const double       time = time_discretization.time(n);

    const StepMeasures measures = displacement_problem.measure_step();
    check_finite(measures, n);
    const double u_max = measures.u_max;
    // The stress of every cell, for the fields and for the scale of the
    // stress error, only where they are needed.
    const bool write
      = output_writer.writes_fields_at(n, time_discretization.n_steps());
    Vector<double>              von_mises;
    std::vector<Vector<double>> components;
    if (write || verification.has_exact_stress())
      displacement_problem.compute_cell_stresses(von_mises, components);

    std::string line = add_step_statistics(n, step_wall_time, measures);
    if (error_estimator.estimates_step(n, time_discretization.n_steps()))
      {
        statistics.add_value("estimate_space", estimate.space);
        statistics.add_value("estimate_time", estimate.time);
      }
    StepReport report{n, time, u_max, components, StepQuantities()};
    report.quantities.damaged_fraction = measures.damaged_fraction;
    for (const auto &add_report : step_reports)
      add_report(line, report);
    if (!output_writer.deterministic_screen_output() && n > 0)
      {
        line += "  CG its = "
                + std::to_string(displacement_problem.linear_iterations());
        for (const Physics<dim> *object : physics)
          line += object->iteration_counts();
        line += printf_text("  (%.3f s)", step_wall_time);
      }
    pcout << line << std::endl;

    if (write)
      write_fields(n, von_mises, components);
    output_writer.write_statistics(statistics, mpi_communicator);
  }



  template <int dim>
  void
  Simulator<dim>::write_fields(const unsigned int                 n,
                               const Vector<double>              &von_mises,
                               const std::vector<Vector<double>> &components)
  {
    // The solution: displacement (a vector) and, in damage scenes, zeta,
    // at the vertices; the physics objects' nodal fields (the contact
    // nodes' status and traction); the stresses per cell and their ranks.
    // The piece copies them here, where the ranks exchange ghost values
    // together, and is compressed and written with the write.
    const LA::MPI::Vector   &solution = displacement_problem.ghosted_solution();
    PieceBuilder<dim>        piece(dof_handler, solution);
    std::vector<std::string> names(dim, "displacement");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    for (const Physics<dim> *object : physics)
      for (const std::string &name : object->solution_field_names())
        {
          names.push_back(name);
          interpretation.push_back(
            DataComponentInterpretation::component_is_scalar);
        }
    piece.add_point_fields(solution, names, interpretation);

    LA::MPI::Vector ghosted(solution);
    for (const Physics<dim> *object : physics)
      for (const NodalField<dim> &field : object->output_fields(output_layout))
        {
          output_ghosts.copy(field.values, ghosted);
          piece.add_point_fields(ghosted, *field.postprocessor);
        }

    piece.add_cell_field(von_mises, "von_mises");
    const auto names_of_stress = stress_component_names<dim>();
    for (unsigned int c = 0; c < components.size(); ++c)
      piece.add_cell_field(components[c], names_of_stress[c]);
    Vector<double> subdomain(von_mises.size());
    subdomain = mesh->locally_owned_subdomain();
    piece.add_cell_field(subdomain, "subdomain");
    output_writer.write_fields(piece.take(),
                               n,
                               time_discretization.time(n),
                               n < time_discretization.n_steps(),
                               mpi_communicator);
  }



  template <int dim>
  void
  Simulator<dim>::print_summary(const double wall_time) const
  {
    pcout << '\n' << verification.summary();
    if (error_estimator.is_active())
      {
        // The estimate next to the run time: what a result is worth and
        // what it cost.
        const ErrorEstimate largest = error_estimator.largest();
        pcout << "Estimated error (Theorem 2's norm, largest over the steps): "
              << printf_text("%.3e", largest.sum()) << " (space "
              << printf_text("%.3e", largest.space) << ", time "
              << printf_text("%.3e", largest.time) << "); relative to the "
              << "solution's norm at its step at most "
              << printf_text("%.3g %%",
                             100. * error_estimator.largest_parts().relative);
        if (!output_writer.deterministic_screen_output())
          pcout << " in " << printf_text("%.3g", wall_time) << " s of run time";
        pcout << '\n';
      }
    for (const Physics<dim> *object : physics)
      pcout << object->violation_summary();
    pcout << "Run complete: " << time_discretization.n_steps()
          << " steps; statistics in "
          << "statistics.csv";
    if (!output_writer.deterministic_screen_output())
      {
        pcout << " (folder " << output_writer.directory() << ")" << std::endl;
        computing_timer.print_summary();
        // On several ranks, each phase's time on the slowest and the
        // fastest rank: how evenly the work is spread.
        if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
          computing_timer.print_wall_time_statistics(mpi_communicator);
        for (const Physics<dim> *object : physics)
          pcout << object->work_summary();
        // Peak resident memory of this rank (VmHWM), for the benchmarks.
        std::ifstream status("/proc/self/status");
        for (std::string line; std::getline(status, line);)
          if (line.rfind("VmHWM:", 0) == 0)
            pcout << "Peak memory (rank 0): " << line.substr(6) << std::endl;
      }
    pcout << std::endl;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
