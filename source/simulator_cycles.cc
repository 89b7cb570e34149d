// The simulator's refinement cycles: the mesh and step of each cycle, the
// snapshots and errors against a reference run, and the convergence table.
#include <vpcontact/input_error.h>
#include <vpcontact/simulator.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace VPContact
{
  template <int dim>
  void
  Simulator<dim>::start_cycle(const unsigned int cycle)
  {
    // A cycle is a new run: its own folder (with more than one cycle), its
    // own time grid, and no state of the previous cycle's run.
    current_cycle = cycle;
    if (mesh_refinement.n_cycles() > 1)
      {
        output_writer.set_subfolder("cycle-" + std::to_string(cycle));
        output_writer.prepare_directory(mpi_communicator);
        pcout << "Cycle " << cycle << " of " << mesh_refinement.n_cycles()
              << " (" << mesh_refinement.description() << ")" << std::endl;
      }
    const double h = equivalent_mesh_size(triangulation);
    if (cycle == 0)
      first_mesh_size = h;
    {
      const auto box   = GridTools::compute_bounding_box(triangulation);
      Point<dim> lower = box.get_boundary_points().first,
                 upper = box.get_boundary_points().second;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = Utilities::MPI::min(lower[d], mpi_communicator);
          upper[d] = Utilities::MPI::max(upper[d], mpi_communicator);
        }
      body_size = lower.distance(upper);
    }
    time_discretization.set_halvings(
      mesh_refinement.time_step_halvings(first_mesh_size, h));

    statistics                 = Statistics();
    last_linear_iterations     = 0;
    last_active_set_iterations = 0;
    max_friction_violation     = 0;
    diagnostics_time           = 0;
    compared_times             = 0;
    max_error                  = ErrorNorms();
    max_error_sum              = 0;
    const double nan           = std::numeric_limits<double>::quiet_NaN();
    final_error                = ErrorNorms{nan, nan, nan};
    verification.restore_running_maxima({}); // each cycle's summary is its own
    computing_timer.reset();
    error_indicator.reinit(triangulation);
  }



  template <int dim>
  void
  Simulator<dim>::refine_mesh()
  {
    // The quadrature point data live on the cells of the old mesh; the next
    // cycle starts from t = 0 and sets them up again.
    stress_history.clear();
    mesh_refinement.refine(triangulation,
                           error_indicator.values(),
                           boundary_conditions.contact_boundary_ids());
  }



  template <int dim>
  void
  Simulator<dim>::finish_cycle(const unsigned int cycle, const double wall_time)
  {
    ConvergenceTable::Row row;
    row.cycle     = cycle;
    row.cells     = triangulation.n_global_active_cells();
    row.dofs      = dof_handler.n_dofs();
    row.h         = equivalent_mesh_size(triangulation);
    row.k         = time_discretization.step_size();
    row.steps     = time_discretization.n_steps();
    row.wall_time = wall_time;
    row.cumulative_wall_time
      = wall_time
        + (convergence_table.rows().empty() ?
             0. :
             convergence_table.rows().back().cumulative_wall_time);
    row.has_errors     = reference_solution.compares();
    row.max_error      = max_error;
    row.max_error_sum  = max_error_sum;
    row.final_error    = final_error;
    row.compared_times = compared_times;
    convergence_table.add_row(row);

    if (mesh_refinement.n_cycles() > 1 || reference_solution.compares())
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        write_file_atomically(output_writer.base_directory()
                                + "/convergence.csv",
                              convergence_table.to_csv());
  }



  template <int dim>
  Snapshot<dim>
  Simulator<dim>::make_snapshot(const double time) const
  {
    // This rank's cells: vertices, nodal displacement and damage, and the
    // stress at the quadrature points.
    Snapshot<dim> snapshot;
    snapshot.time                            = time;
    snapshot.has_damage                      = damage_model.is_active();
    constexpr unsigned int                 V = Snapshot<dim>::n_vertices;
    std::array<Point<dim>, V>              vertices;
    std::array<Tensor<1, dim>, V>          u;
    std::array<double, V>                  zeta;
    std::array<SymmetricTensor<2, dim>, V> sigma;
    AssertThrow(quadrature.size() == V, ExcInternalError());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          for (unsigned int v = 0; v < V; ++v)
            {
              vertices[v] = cell->vertex(v);
              for (unsigned int d = 0; d < dim; ++d)
                u[v][d] = solution(cell->vertex_dof_index(v, d));
              zeta[v] = (snapshot.has_damage ?
                           solution(cell->vertex_dof_index(v, dim)) :
                           1.);
            }
          const auto history = stress_history.get_data(cell);
          for (unsigned int q = 0; q < V; ++q)
            sigma[q] = history[q].stress;
          snapshot.add_cell(cell->id(), vertices, u, zeta, sigma);
        }
    return snapshot;
  }



  template <int dim>
  void
  Simulator<dim>::add_reference_statistics(std::string       &line,
                                           const unsigned int n)
  {
    // Snapshots for a later comparison (in the last cycle), and the errors
    // against the reference where it has this time. Both are diagnostics:
    // their time is not counted as the run's.
    Timer        timer;
    const double time = time_discretization.time(n);
    const bool   write
      = reference_solution.writes_snapshots()
        && current_cycle + 1 == mesh_refinement.n_cycles()
        && reference_solution.is_snapshot_step(n,
                                               time_discretization.step_size());
    const bool compare
      = reference_solution.compares() && reference_solution.has_time(time);
    if (!write && !compare)
      return;

    const Snapshot<dim> local = make_snapshot(time);
    if (write)
      reference_solution.write(local, mpi_communicator);
    if (compare)
      {
        const ErrorNorms errors
          = compute_errors(local,
                           reference_solution.template read<dim>(time),
                           reference_solution.comparison_folder(),
                           mpi_communicator);
        ++compared_times;
        max_error.displacement
          = std::max(max_error.displacement, errors.displacement);
        max_error.stress = std::max(max_error.stress, errors.stress);
        max_error.damage = std::max(max_error.damage, errors.damage);
        max_error_sum    = std::max(max_error_sum, errors.sum());
        if (n == time_discretization.n_steps())
          final_error = errors;
        statistics.add_value("error_u", errors.displacement);
        statistics.add_value("error_stress", errors.stress);
        statistics.add_value("error_damage", errors.damage);
        char text[128];
        std::snprintf(text,
                      sizeof(text),
                      "  error vs reference: u %.4e, sigma %.4e, zeta %.4e",
                      errors.displacement,
                      errors.stress,
                      errors.damage);
        line += text;
      }
    timer.stop();
    diagnostics_time += timer.wall_time();
  }



  template <int dim>
  void
  Simulator<dim>::print_convergence_table() const
  {
    if (mesh_refinement.n_cycles() == 1 && !reference_solution.compares())
      return;
    pcout << "\nConvergence table ("
          << (reference_solution.compares() ?
                "errors against " + reference_solution.comparison_folder()
                  + ", largest over the common times; order against the "
                    "previous row in h = (|Omega|/cells)^(1/dim)" :
                "no reference to compare with: Reference solution/Compare "
                "with")
          << "; also in " << output_writer.base_directory()
          << "/convergence.csv):\n"
          << convergence_table.to_text(
               !output_writer.deterministic_screen_output())
          << std::endl;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
