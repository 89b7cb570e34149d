// Checks MeshTransfer, which carries a run's state through a change of its
// distributed mesh (Mesh refinement/Adapt during run), on the rectangle
// [0, 2] x [0, 1] of 4 x 2 cells refined once, with the FESystem of a damage
// scene (Q1 displacement and damage) and the stress history at the 2 x 2
// Gauss points:
// - fields the coarse mesh represents come through refinement, and back
//   through coarsening, unchanged to round-off: a linear displacement, a
//   bilinear damage in [0, 1], and every value at the points bilinear in x
//   and y (one polynomial per value);
// - a field it cannot represent (sin and cos at the points) is averaged when
//   its cells are coarsened: each parent keeps its children's mean, and
//   refining the averaged field and coarsening it again gives it back;
// - the damage stays in [0, 1] at every node after every change.
// On 2 ranks p4est moves cells between the ranks with each change.
#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/refinement/mesh_transfer.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

using namespace VPContact;

namespace
{
  constexpr unsigned int n_values = QuadraturePointHistory<2>::n_values;
  using PointValue = std::function<double(unsigned int, const Point<2> &)>;

  // Value i at a point: bilinear (represented), or not.
  double
  bilinear(const unsigned int i, const Point<2> &p)
  {
    return 1. + i + (0.5 + i) * p[0] - 0.3 * i * p[1] + 0.25 * i * p[0] * p[1];
  }

  double
  smooth(const unsigned int i, const Point<2> &p)
  {
    return std::sin(3 * p[0] + i) * std::cos(2 * p[1]);
  }

  // u = (1 + 2x - y, 0.5x + 3y), zeta = 0.1 + 0.2x + 0.15xy in [0.1, 0.8].
  class Fields : public Function<2>
  {
  public:
    Fields()
      : Function<2>(3)
    {}
    double
    value(const Point<2> &p, const unsigned int c) const override
    {
      return c == 0 ? 1 + 2 * p[0] - p[1] :
             c == 1 ? 0.5 * p[0] + 3 * p[1] :
                      0.1 + 0.2 * p[0] + 0.15 * p[0] * p[1];
    }
  };

  struct State
  {
    parallel::distributed::Triangulation<2> mesh{MPI_COMM_WORLD};
    FESystem<2>                             fe{FE_Q<2>(1), 2, FE_Q<2>(1), 1};
    DoFHandler<2>                           dofs{mesh};
    QGauss<2>                               quadrature{2};
    StressHistory<2>                        history;
    LA::MPI::Vector                         solution; // ghosted
    IndexSet                                owned, relevant;

    void
    setup()
    {
      dofs.distribute_dofs(fe);
      owned = dofs.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      solution.reinit(owned, relevant, MPI_COMM_WORLD);
      history.clear();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          history.initialize(cell, quadrature.size());
    }

    // Calls visit(cell, values, q, v) at every point q of the owned cells,
    // with values reinitialized on the cell (@p flags) and v the point's
    // values; with @p store, what visit leaves in v is the point's new
    // values.
    template <typename Visit>
    void
    for_each_point(const UpdateFlags flags,
                   const Visit      &visit,
                   const bool        store = false)
    {
      FEValues<2> values(fe, quadrature, flags);
      history.keep_initial_rates();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            values.reinit(cell);
            auto points  = history.get_data(cell);
            auto rates   = history.initial_rates(cell);
            auto sources = history.damage_sources(cell);
            for (unsigned int q = 0; q < points.size(); ++q)
              {
                double v[n_values];
                points[q].write_to(v, rates[q], sources[q]);
                visit(cell, values, q, v);
                if (store)
                  points[q].read_from(v, rates[q], sources[q]);
              }
          }
    }

    // Each point's values from @p f at its position.
    void
    set_history(const PointValue &f)
    {
      for_each_point(
        update_quadrature_points,
        [&](const auto &,
            const FEValues<2> &values,
            unsigned int       q,
            double            *v) {
          for (unsigned int i = 0; i < n_values; ++i)
            v[i] = f(i, values.quadrature_point(q));
        },
        true);
    }

    // The largest difference of a value at a point from @p f there.
    double
    history_error(const PointValue &f)
    {
      double error = 0;
      for_each_point(update_quadrature_points,
                     [&](const auto &,
                         const FEValues<2> &values,
                         unsigned int       q,
                         double            *v) {
                       for (unsigned int i = 0; i < n_values; ++i)
                         error = std::max(
                           error,
                           std::abs(v[i] - f(i, values.quadrature_point(q))));
                     });
      return Utilities::MPI::max(error, MPI_COMM_WORLD);
    }

    // The flagged change, with the solution and the history carried over.
    void
    change()
    {
      MeshTransfer<2> transfer(mesh, dofs, quadrature);
      transfer.prepare({&solution}, history);
      mesh.execute_coarsening_and_refinement();
      setup();
      LA::MPI::Vector owned_solution(owned, MPI_COMM_WORLD);
      transfer.unpack({&owned_solution}, history);
      AffineConstraints<double> hanging(relevant);
      DoFTools::make_hanging_node_constraints(dofs, hanging);
      hanging.close();
      hanging.distribute(owned_solution);
      solution = owned_solution;
    }

    // Largest nodal error against Fields, and the damage's range.
    std::array<double, 3>
    nodal_check() const
    {
      LA::MPI::Vector exact(owned, MPI_COMM_WORLD);
      VectorTools::interpolate(dofs, Fields(), exact);
      LA::MPI::Vector difference(owned, MPI_COMM_WORLD);
      difference = solution;
      difference -= exact;
      double                               low = 1, high = 0;
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              if (fe.system_to_component_index(i).first == 2)
                {
                  low  = std::min(low, solution(indices[i]));
                  high = std::max(high, solution(indices[i]));
                }
          }
      return {difference.linfty_norm(),
              Utilities::MPI::min(low, MPI_COMM_WORLD),
              Utilities::MPI::max(high, MPI_COMM_WORLD)};
    }

    // The values at the points of every active cell, by cell id, from all
    // ranks.
    std::map<std::string, std::vector<double>>
    values_by_cell()
    {
      std::map<std::string, std::vector<double>> own;
      for_each_point(
        update_default,
        [&](const auto &cell, const FEValues<2> &, unsigned int, double *v) {
          auto &values = own[cell->id().to_string()];
          values.insert(values.end(), v, v + n_values);
        });
      std::map<std::string, std::vector<double>> all;
      for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, own))
        all.insert(part.begin(), part.end());
      return all;
    }

    // Flag the active cells whose centre is left of x = 0.7 for refinement,
    // or their parents' children for coarsening.
    void
    flag(const bool refine)
    {
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned() && cell->center()[0] < 0.7)
          {
            if (refine)
              cell->set_refine_flag();
            else if (cell->level() > 1)
              cell->set_coarsen_flag();
          }
    }

    // The integral of every value over the mesh, which coarsening by
    // projection keeps (the children of a parent have equal measure here).
    std::vector<double>
    integrals()
    {
      std::vector<double> sums(n_values, 0.);
      for_each_point(update_JxW_values,
                     [&](const auto &,
                         const FEValues<2> &values,
                         unsigned int       q,
                         double            *v) {
                       for (unsigned int i = 0; i < n_values; ++i)
                         sums[i] += v[i] * values.JxW(q);
                     });
      for (auto &s : sums)
        s = Utilities::MPI::sum(s, MPI_COMM_WORLD);
      return sums;
    }
  };

  void
  report(const char *what, State &state, const PointValue &f)
  {
    const auto   nodal   = state.nodal_check();
    const double history = state.history_error(f);
    std::printf("%s: %u cells; nodal fields exact to 1e-13: %s; values at "
                "the points exact to 1e-13: %s; damage in [0, 1]: %s\n",
                what,
                state.mesh.n_global_active_cells(),
                nodal[0] < 1e-13 ? "yes" : "NO",
                history < 1e-13 ? "yes" : "NO",
                nodal[1] >= 0 && nodal[2] <= 1 ? "yes" : "NO");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);

  State state;
  GridGenerator::subdivided_hyper_rectangle(state.mesh,
                                            {4, 2},
                                            Point<2>(0, 0),
                                            Point<2>(2, 1));
  state.mesh.refine_global(1);
  state.setup();
  VectorTools::interpolate(state.dofs, Fields(), state.solution);
  LA::MPI::Vector initial(state.owned, MPI_COMM_WORLD);
  VectorTools::interpolate(state.dofs, Fields(), initial);
  state.solution = initial;
  state.set_history(bilinear);
  report("start", state, bilinear);

  state.flag(true);
  state.change();
  report("refined left of x = 0.7", state, bilinear);
  state.flag(true);
  state.change();
  report("refined there again", state, bilinear);
  state.flag(false);
  state.change();
  report("coarsened there once", state, bilinear);

  // A field the mesh cannot represent, on the finest cells.
  state.flag(true);
  state.change();
  state.set_history(smooth);
  const std::vector<double> before = state.integrals();
  state.flag(false);
  state.change();
  const std::vector<double> after = state.integrals();
  double                    kept  = 0;
  for (unsigned int i = 0; i < n_values; ++i)
    kept = std::max(kept, std::abs(after[i] - before[i]));
  std::printf("sin/cos values coarsened: every value's integral kept to "
              "1e-13: %s\n",
              kept < 1e-13 ? "yes" : "NO");

  // Refining the averaged field and coarsening again gives it back: the
  // values of every cell, gathered by cell id on all ranks since p4est may
  // give a cell to another rank.
  const auto averaged = state.values_by_cell();
  state.flag(true);
  state.change();
  state.flag(false);
  state.change();
  const auto again  = state.values_by_cell();
  double     change = 0, largest = 0;
  for (const auto &[id, values] : again)
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        change  = std::max(change, std::abs(values[k] - averaged.at(id)[k]));
        largest = std::max(largest, std::abs(values[k]));
      }
  std::printf("the coarsened sin/cos values refined and coarsened again come "
              "back to 1e-13: %s (%zu cells compared, values up to %.2f)\n",
              change < 1e-13 && again.size() == averaged.size() ? "yes" : "NO",
              again.size(),
              largest);
  const auto nodal = state.nodal_check();
  std::printf("after all this: nodal fields exact to 1e-13: %s; damage in "
              "[0, 1]: %s\n",
              nodal[0] < 1e-13 ? "yes" : "NO",
              nodal[1] >= 0 && nodal[2] <= 1 ? "yes" : "NO");
}
