// The displacement at the monitor points: parsing, locating the points on
// the distributed mesh, and evaluating the displacement there after a step.
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/postprocess/monitor_points.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace VPContact
{
  template <int dim>
  void
  MonitorPoints<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry(
      "Monitor points",
      "",
      Patterns::Anything(),
      "Points of the body (reference configuration) where the displacement "
      "is written into statistics.csv after every step, as the columns "
      "monitor1_ux, monitor1_uy (monitor1_uz), monitor2_ux, ...: the value of "
      "the finite element function at the point. Points are separated by "
      "semicolons and their coordinates by commas, e.g. '1, 0; 1, 1'.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  MonitorPoints<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    const std::string text = prm.get("Monitor points");
    prm.leave_subsection();
    points.clear();
    for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto coordinates = Utilities::split_string_list(item, ',');
        VPContactCheckParameter(coordinates.size() == dim,
                                "Output/Monitor points",
                                text,
                                "the point '" + item + "' has "
                                  + std::to_string(coordinates.size())
                                  + " coordinates, a " + std::to_string(dim)
                                  + "D scene needs " + std::to_string(dim)
                                  + " per point, separated by commas; "
                                    "points are separated by semicolons.");
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          {
            char        *end   = nullptr;
            const double value = std::strtod(coordinates[d].c_str(), &end);
            VPContactCheckParameter(end != coordinates[d].c_str()
                                      && *end == '\0' && std::isfinite(value),
                                    "Output/Monitor points",
                                    text,
                                    "'" + coordinates[d]
                                      + "' is not a finite number.");
            p[d] = value;
          }
        points.push_back(p);
      }
  }



  template <int dim>
  void
  MonitorPoints<dim>::setup(const DoFHandler<dim> &dof_handler)
  {
    communicator = dof_handler.get_communicator();
    locations.clear();
    n_evaluations.assign(points.size(), 0);
    const Mapping<dim> &mapping
      = get_default_linear_mapping(dof_handler.get_triangulation());
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        // The first locally owned cell around the point, if any: a point on
        // a face or vertex has several, possibly on several ranks.
        const auto cells
          = GridTools::find_all_active_cells_around_point(mapping,
                                                          dof_handler,
                                                          points[i]);
        for (const auto &[cell, unit_point] : cells)
          if (cell->is_locally_owned())
            {
              locations.push_back(
                {i,
                 cell,
                 cell->reference_cell().is_hyper_cube() ?
                   GeometryInfo<dim>::project_to_unit_cell(unit_point) :
                   unit_point});
              n_evaluations[i] = 1;
              break;
            }
      }
    Utilities::MPI::sum(n_evaluations, communicator, n_evaluations);
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        std::ostringstream where;
        for (unsigned int d = 0; d < dim; ++d)
          where << (d > 0 ? ", " : "") << points[i][d];
        VPContactCheckParameter(n_evaluations[i] > 0,
                                "Output/Monitor points",
                                where.str(),
                                "the point is not in the body. Give points "
                                "of the reference configuration.");
      }
  }



  template <int dim>
  void
  MonitorPoints<dim>::add_statistics(const LA::MPI::Vector &solution,
                                     Statistics            &statistics) const
  {
    if (points.empty())
      return;
    std::vector<double> values(points.size() * dim, 0.);
    for (const auto &location : locations)
      {
        const Mapping<dim> &mapping
          = get_default_linear_mapping(location.cell->get_triangulation());
        const auto   &fe = location.cell->get_fe();
        FEValues<dim> fe_values(mapping,
                                fe,
                                Quadrature<dim>(location.unit_point),
                                update_values);
        fe_values.reinit(location.cell);
        std::vector<Vector<double>> at_point(1,
                                             Vector<double>(fe.n_components()));
        fe_values.get_function_values(solution, at_point);
        for (unsigned int d = 0; d < dim; ++d)
          values[location.point * dim + d] = at_point[0][d];
      }
    Utilities::MPI::sum(values, communicator, values);
    const char *axis[] = {"x", "y", "z"};
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        statistics.add_value("monitor" + std::to_string(i + 1) + "_u" + axis[d],
                             values[i * dim + d] / n_evaluations[i]);
  }



  template class MonitorPoints<2>;
  template class MonitorPoints<3>;
} // namespace VPContact
