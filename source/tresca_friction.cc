// The section "Contact": the Tresca friction bound and its checks.
#include <vpcontact/input_error.h>
#include <vpcontact/parsed_function.h>
#include <vpcontact/tresca_friction.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace VPContact
{
  template <int dim>
  void
  TrescaFriction<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    {
      prm.declare_entry("Friction bound",
                        "1000",
                        Patterns::Anything(),
                        "Tresca friction bound g(x, t) >= 0 on the contact "
                        "boundary [N/m^2], an expression in x, y (z) and t. "
                        "Not yet used: in this release the contact boundary "
                        "is frictionless (g = 0); the value is checked.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  TrescaFriction<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    friction_bound
      = parse_function_entry<dim>(prm, "Contact", "Friction bound", 1);
    prm.leave_subsection();
  }



  template <int dim>
  void
  TrescaFriction<dim>::check_bound(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const std::set<types::boundary_id>              &contact_ids,
    const std::vector<double>                       &times) const
  {
    // The smallest value over the contact vertices of this rank and the
    // given times; then over all ranks, so that every rank decides alike.
    double     g_min = std::numeric_limits<double>::max();
    Point<dim> where;
    double     when = 0;
    for (const double t : times)
      {
        friction_bound->set_time(t);
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && contact_ids.count(face->boundary_id()))
                for (const unsigned int v : face->vertex_indices())
                  {
                    const double g = friction_bound->value(face->vertex(v));
                    if (!(g >= g_min)) // also true for NaN
                      {
                        g_min = (std::isnan(g) ? -1. : g);
                        where = face->vertex(v);
                        when  = t;
                      }
                  }
      }
    const double global_min
      = Utilities::MPI::min(g_min, triangulation.get_communicator());
    // The rank holding the minimum tells where it is.
    const unsigned int holder = Utilities::MPI::min(
      g_min == global_min ?
        Utilities::MPI::this_mpi_process(triangulation.get_communicator()) :
        Utilities::MPI::n_mpi_processes(triangulation.get_communicator()),
      triangulation.get_communicator());
    std::ostringstream location;
    location << "(" << where << ") at t = " << when;
    const std::string text
      = Utilities::MPI::broadcast(triangulation.get_communicator(),
                                  location.str(),
                                  holder);
    VPContactCheckParameter(global_min >= 0,
                            "Contact/Friction bound",
                            global_min,
                            "the friction bound must be non-negative and "
                            "finite on the contact boundary; this is its "
                            "value at x = "
                              + text + ".");
  }



  template class TrescaFriction<2>;
  template class TrescaFriction<3>;
} // namespace VPContact
