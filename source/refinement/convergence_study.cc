// The convergence study: refinement cycles, the time step of each cycle,
// snapshots and errors against a reference run, and the convergence table.
#include <vpcontact/input/input_error.h>
#include <vpcontact/postprocess/output_writer.h>
#include <vpcontact/refinement/convergence_study.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace VPContact
{
  template <int dim>
  void
  ConvergenceStudy<dim>::declare_parameters(ParameterHandler &prm)
  {
    MeshRefinement<dim>::declare_parameters(prm);
    ReferenceSolution::declare_parameters(prm);
  }



  template <int dim>
  void
  ConvergenceStudy<dim>::parse_parameters(ParameterHandler         &prm,
                                          const std::string        &directory,
                                          const TimeDiscretization &time,
                                          const unsigned int        base_level)
  {
    mesh_refinement.parse_parameters(prm, base_level);
    reference_solution.parse_parameters(prm, directory);
    reference_solution.check_time_step(time.step_size(), time.end_time());
  }



  template <int dim>
  const MeshRefinement<dim> &
  ConvergenceStudy<dim>::refinement() const
  {
    return mesh_refinement;
  }



  template <int dim>
  unsigned int
  ConvergenceStudy<dim>::n_cycles() const
  {
    return mesh_refinement.n_cycles();
  }



  template <int dim>
  void
  ConvergenceStudy<dim>::prepare(const MPI_Comm communicator)
  {
    if (reference_solution.compares())
      reference_solution.read_index(communicator);
  }



  template <int dim>
  unsigned int
  ConvergenceStudy<dim>::start_cycle(
    const unsigned int                      cycle,
    const parallel::TriangulationBase<dim> &triangulation)
  {
    current_cycle  = cycle;
    const double h = equivalent_mesh_size(triangulation);
    if (cycle == 0)
      first_mesh_size = h;
    diagnostics      = 0;
    compared_times   = 0;
    max_error        = ErrorNorms();
    max_error_sum    = 0;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    final_error      = ErrorNorms{nan, nan, nan};
    halvings
      = (cycle > 0 && mesh_refinement.time_step_from_estimate() ?
           halvings_from_estimate(triangulation.n_global_active_cells()) :
           mesh_refinement.time_step_halvings(first_mesh_size, h));
    return halvings;
  }



  template <int dim>
  void
  ConvergenceStudy<dim>::check_reference_times(
    const TimeDiscretization &time) const
  {
    if (!reference_solution.compares())
      return;
    reference_solution.check_common_times(
      time.step_size(),
      time.n_steps(),
      [&time](const unsigned int n) { return time.time(n); },
      "Time/Time step = "
        + (halvings == 0 ? to_text(time.step_size()) :
                           to_text(time.step_size() * std::pow(2., halvings))
                             + ", halved to " + to_text(time.step_size())
                             + " in cycle " + std::to_string(current_cycle)));
  }



  template <int dim>
  unsigned int
  ConvergenceStudy<dim>::halvings_from_estimate(
    const unsigned long long cells) const
  {
    // The time part T is proportional to k; the space part S of the new
    // mesh is predicted from the last one's as first order in the
    // equivalent mesh size, S ~ cells^(-1/dim). A run costs about cells/k,
    // and the cheapest (cells, k) for a given S + T has T = S/dim. k is
    // halved (or doubled) the whole number of times that brings T nearest
    // to that.
    const ConvergenceTable::Row &last = convergence_table.rows().back();
    AssertThrow(last.has_estimate && last.estimate_parts.space > 0
                  && last.estimate_parts.time > 0,
                ExcMessage("Mesh refinement/Time step from error estimate: "
                           "the previous cycle has no space and time parts "
                           "to choose k from. Set Error estimate/Estimate "
                           "error = true, or set this entry to false."));
    const double predicted_space
      = last.estimate_parts.space
        * std::pow(static_cast<double>(last.cells) / cells, 1. / dim);
    const long change = std::lround(
      std::log2(dim * last.estimate_parts.time / predicted_space));
    return static_cast<unsigned int>(
      std::clamp<long>(static_cast<long>(halvings) + change, 0, 30));
  }



  template <int dim>
  void
  ConvergenceStudy<dim>::refine(
    parallel::TriangulationBase<dim>   &triangulation,
    const Vector<float>                &indicators,
    const std::set<types::boundary_id> &contact_boundary_ids)
  {
    mesh_refinement.refine(triangulation, indicators, contact_boundary_ids);
  }



  template <int dim>
  void
  ConvergenceStudy<dim>::add_reference_statistics(
    const unsigned int                    n,
    const TimeDiscretization             &time,
    const std::function<Snapshot<dim>()> &snapshot,
    Statistics                           &statistics,
    std::string                          &line,
    const MPI_Comm                        communicator)
  {
    // Both are diagnostics: their time is not counted as the run's.
    Timer        timer;
    const double t = time.time(n);
    const bool   write
      = reference_solution.writes_snapshots()
        && current_cycle + 1 == mesh_refinement.n_cycles()
        && reference_solution.is_snapshot_step(n, time.step_size());
    const bool compare
      = reference_solution.compares() && reference_solution.has_time(t);
    if (!write && !compare)
      return;

    const Snapshot<dim> local = snapshot();
    if (write)
      reference_solution.write(local, communicator);
    if (compare)
      {
        const ErrorNorms errors
          = compute_errors(local,
                           reference_solution.template read<dim>(t,
                                                                 communicator),
                           reference_solution.comparison_folder(),
                           communicator);
        ++compared_times;
        max_error.displacement
          = std::max(max_error.displacement, errors.displacement);
        max_error.stress = std::max(max_error.stress, errors.stress);
        max_error.damage = std::max(max_error.damage, errors.damage);
        max_error_sum    = std::max(max_error_sum, errors.sum());
        if (n == time.n_steps())
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
    diagnostics += timer.wall_time();
  }



  template <int dim>
  double
  ConvergenceStudy<dim>::diagnostics_time() const
  {
    return diagnostics;
  }



  template <int dim>
  void
  ConvergenceStudy<dim>::finish_cycle(
    const parallel::TriangulationBase<dim> &triangulation,
    const types::global_dof_index           n_dofs,
    const TimeDiscretization               &time,
    const ErrorEstimator<dim>              &estimator,
    const double                            wall_time,
    const std::string                      &base_directory,
    const MPI_Comm                          communicator)
  {
    ConvergenceTable::Row row;
    row.cycle     = current_cycle;
    row.cells     = triangulation.n_global_active_cells();
    row.dofs      = n_dofs;
    row.h         = equivalent_mesh_size(triangulation);
    row.k         = time.step_size();
    row.steps     = time.n_steps();
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
    row.has_estimate   = estimator.is_active();
    if (row.has_estimate)
      {
        row.estimate       = estimator.largest();
        row.estimate_parts = estimator.largest_parts();
      }
    convergence_table.add_row(row);

    if (mesh_refinement.n_cycles() > 1 || reference_solution.compares())
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        write_file_atomically(base_directory + "/convergence.csv",
                              convergence_table.to_csv());
  }



  template <int dim>
  std::string
  ConvergenceStudy<dim>::table_text(const std::string &base_directory,
                                    const bool         deterministic) const
  {
    if (mesh_refinement.n_cycles() == 1 && !reference_solution.compares())
      return "";
    std::ostringstream out;
    out << "\nConvergence table ("
        << (reference_solution.compares() ?
              "errors against " + reference_solution.comparison_folder()
                + ", largest over the common times; order against the "
                  "previous row in h = (|Omega|/cells)^(1/dim)" :
              "no reference to compare with: Reference solution/Compare "
              "with")
        << "; also in " << base_directory << "/convergence.csv):\n"
        << convergence_table.to_text(!deterministic) << '\n';
    return out.str();
  }



  template class ConvergenceStudy<2>;
  template class ConvergenceStudy<3>;
} // namespace VPContact
