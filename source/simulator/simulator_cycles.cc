// The simulator's refinement cycles: the start of a cycle, the next mesh, and
// the snapshot of the solution that ConvergenceStudy compares.
#include <vpcontact/input/input_error.h>
#include <vpcontact/simulator/simulator.h>

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
    if (convergence_study.n_cycles() > 1)
      {
        output_writer.set_subfolder("cycle-" + std::to_string(cycle));
        output_writer.prepare_directory(mpi_communicator);
        pcout << "Cycle " << cycle << " of " << convergence_study.n_cycles()
              << " (" << convergence_study.refinement().description() << ")"
              << std::endl;
      }
    time_discretization.set_halvings(
      convergence_study.start_cycle(cycle, *mesh));
    convergence_study.check_reference_times(time_discretization);

    statistics = Statistics();
    displacement_problem.reset_linear_iterations();
    displacement_problem.restore_solver_choice({});
    verification.restore_running_maxima({}); // each cycle's summary is its own
  }



  template <int dim>
  void
  Simulator<dim>::refine_mesh()
  {
    // The quadrature point data live on the cells of the old mesh; the next
    // cycle starts from t = 0 and sets them up again.
    displacement_problem.history().clear();
    convergence_study.refine(
      *mesh,
      error_estimator.cell_indicators(),
      displacement_problem.boundaries().contact_boundary_ids());
  }



  template <int dim>
  Snapshot<dim>
  Simulator<dim>::make_snapshot(const double time) const
  {
    // This rank's cells: vertices, nodal displacement and damage, and the
    // stress at the quadrature points.
    const LA::MPI::Vector &solution = displacement_problem.ghosted_solution();
    Snapshot<dim>          snapshot;
    snapshot.time = time;
    // The element's layout says whether zeta is a component of it.
    snapshot.has_damage = discretization.finite_element().n_components() > dim;
    constexpr unsigned int                 V = Snapshot<dim>::n_vertices;
    std::array<Point<dim>, V>              vertices;
    std::array<Tensor<1, dim>, V>          u;
    std::array<double, V>                  zeta;
    std::array<SymmetricTensor<2, dim>, V> sigma;
    AssertThrow(discretization.quadrature().size() == V, ExcInternalError());
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
          const auto history = displacement_problem.history().get_data(cell);
          for (unsigned int q = 0; q < V; ++q)
            sigma[q] = history[q].stress;
          snapshot.add_cell(cell->id(), vertices, u, zeta, sigma);
        }
    return snapshot;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace VPContact
