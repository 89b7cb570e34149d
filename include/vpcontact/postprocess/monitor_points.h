// The displacement at points the user names (Output/Monitor points), written
// into statistics.csv after every step: the quantity to compare between
// meshes, elements and dimensions where a maximum over the body is not.
#ifndef vpcontact_monitor_points_h
#define vpcontact_monitor_points_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/postprocess/statistics.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Points of the reference configuration at which the displacement is
   * evaluated (the finite element function, not the nearest node) after
   * every step, as the columns monitor1_ux, monitor1_uy (monitor1_uz), ...
   * of statistics.csv. On several ranks the ranks that own a cell around a
   * point evaluate it there and the values are averaged, which gives the
   * value of the continuous function on any partition.
   */
  template <int dim>
  class MonitorPoints
  {
  public:
    /// The entry Output/Monitor points.
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read the points; a malformed list is refused naming the entry.
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Find the cells around every point on a new mesh. A point outside the
     * body is refused with a message naming the entry and the point.
     * Collective.
     */
    void
    setup(const DoFHandler<dim> &dof_handler);

    /// The columns of every point from the ghosted @p solution. Collective.
    void
    add_statistics(const LA::MPI::Vector &solution,
                   Statistics            &statistics) const;

  private:
    struct Location
    {
      unsigned int                                   point;
      typename DoFHandler<dim>::active_cell_iterator cell;
      Point<dim>                                     unit_point;
    };

    std::vector<Point<dim>>   points;
    std::vector<Location>     locations;
    std::vector<unsigned int> n_evaluations;
    MPI_Comm                  communicator = MPI_COMM_WORLD;
  };
} // namespace VPContact

#endif
