// The section "Contact": the normal condition, the friction law with its bound
// or coefficient, and their checks.
#include <vpcontact/contact/tresca_friction.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parsed_function.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace VPContact
{
  template <int dim>
  TrescaDecision<dim>
  tresca_decision(const Tensor<1, dim> &lambda,
                  const Tensor<1, dim> &slip,
                  const double          g,
                  const double          c)
  {
    const Tensor<1, dim> z    = lambda + c * slip;
    const double         size = z.norm();
    if (size <= g)
      return {ContactStatus::stick, Tensor<1, dim>(), 0.};
    // Divided entry by entry: Tensor's operator/ multiplies by 1/size, which
    // on a line gives 1 - 1e-16 instead of 1, and a direction that depends on
    // the rounding of the reciprocal.
    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = z[d] / size;
    return {ContactStatus::slip, n, g * c / (size - g)};
  }



  template <int dim>
  double
  complementarity_constant(const double factor,
                           const double youngs_modulus,
                           const double measure)
  {
    return factor * youngs_modulus / (dim == 2 ? measure : std::sqrt(measure));
  }



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
                        "g = 0 everywhere is frictionless sliding (no active "
                        "set iteration is run).");
      declare_law_parameters(prm);
      prm.declare_entry("Maximum active set iterations",
                        "50",
                        Patterns::Integer(1, 10000),
                        "The stick/slip iteration of one step stops the run "
                        "with a message if the sets still change after this "
                        "many iterations.");
      prm.declare_entry(
        "Complementarity factor",
        "1",
        Patterns::Double(0),
        "Scales c in the stick/slip test |lambda + c w| <= g; "
        "c = factor x (Young's modulus) / h with h the "
        "node's size (its boundary length in 2D, the square "
        "root of its boundary area in 3D), of the order of "
        "the stiffness per node. In exact arithmetic any positive value "
        "gives the same solution and changes only the "
        "number of iterations; in floating point a factor "
        "far from 1 lets round-off in lambda or w decide the "
        "sets, so it must lie in [1e-6, 1e6].");
      prm.declare_entry("Slip direction tolerance",
                        "1e-10",
                        Patterns::Double(0),
                        "In 3D, the stick/slip iteration has converged when "
                        "no node changes set and no slip direction (a unit "
                        "vector in the tangent plane) turns by more than "
                        "this; the friction law then holds to about this "
                        "fraction of g. Raise it if an iterative "
                        "displacement solver's tolerance keeps the "
                        "directions from settling. Must lie in [1e-14, "
                        "1e-2]: below, round-off alone turns a direction; "
                        "above, the law is not enforced. (In 2D a direction "
                        "only flips.)");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  TrescaFriction<dim>::declare_law_parameters(ParameterHandler &prm)
  {
    // The entries of the normal condition and of Coulomb's law (in the
    // subsection Contact, entered by the caller).
    prm.declare_entry(
      "Normal condition",
      "bilateral",
      Patterns::Selection("bilateral|unilateral"),
      "'bilateral' (the paper's): the body slides on the foundation and "
      "never leaves it, u.nu = 0 on the contact boundary. 'unilateral' "
      "(Signorini): u.nu <= g_0 with the initial gap g_0 (Initial gap), "
      "sigma_nu <= 0 and sigma_nu (u.nu - g_0) = 0 node by node; the body "
      "lifts off where the load pulls it away, and only nodes in contact "
      "carry friction.");
    prm.declare_entry("Initial gap",
                      "0",
                      Patterns::Anything(),
                      "Unilateral only: g_0(x, t) >= 0, the distance from "
                      "the body's point x to the foundation along the "
                      "foundation's normal [m], an expression in x, y (z) "
                      "and t. 0 for a body that rests on the foundation; "
                      "for a cylinder of radius R touching the plane y = 0 "
                      "at the origin, y.");
    prm.declare_entry("Foundation normal",
                      "",
                      Patterns::Anything(),
                      "Unilateral only: the unit normal nu of a plane "
                      "foundation, pointing from the body into it, dim "
                      "comma-separated values (e.g. 0, -1 for a foundation "
                      "below). Empty: each contact node takes the body's "
                      "outward normal there (a flat contact boundary).");
    prm.declare_entry("Friction law",
                      "Tresca",
                      Patterns::Selection("Tresca|Coulomb"),
                      "'Tresca' (the paper's): the friction bound g is "
                      "Friction bound. 'Coulomb': g = mu |sigma_nu| with mu "
                      "the Friction coefficient and sigma_nu the normal "
                      "stress of the current iterate.");
    prm.declare_entry("Friction coefficient",
                      "0",
                      Patterns::Anything(),
                      "Coulomb only: mu(x) >= 0 on the contact boundary, an "
                      "expression in x, y (z) and t. 0 everywhere is "
                      "frictionless.");
    prm.declare_entry("Coulomb bound tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "Coulomb only: the iteration has converged when no "
                      "node changes set and no bound mu |sigma_nu| moves by "
                      "more than this fraction of the largest bound. Must "
                      "lie in [1e-14, 1e-2].");
  }



  template <int dim>
  void
  TrescaFriction<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    friction_bound
      = parse_function_entry<dim>(prm, "Contact", "Friction bound", 1);
    iteration_cap = prm.get_integer("Maximum active set iterations");
    c_factor      = prm.get_double("Complementarity factor");
    direction_tol = prm.get_double("Slip direction tolerance");
    parse_law(prm);
    prm.leave_subsection();
    check_iteration_constants();
  }



  template <int dim>
  void
  TrescaFriction<dim>::parse_law(ParameterHandler &prm)
  {
    is_unilateral = (prm.get("Normal condition") == "unilateral");
    law = (prm.get("Friction law") == "Coulomb" ? FrictionLaw::coulomb :
                                                  FrictionLaw::tresca);
    friction_coefficient
      = parse_function_entry<dim>(prm, "Contact", "Friction coefficient", 1);
    gap       = parse_function_entry<dim>(prm, "Contact", "Initial gap", 1);
    bound_tol = prm.get_double("Coulomb bound tolerance");
    foundation.reset();
    const std::string normal_text = prm.get("Foundation normal");
    if (Utilities::trim(normal_text).empty())
      return;
    std::vector<double> values;
    try
      {
        values = Utilities::string_to_double(
          Utilities::split_string_list(normal_text));
      }
    catch (...)
      {
        values.clear();
      }
    Tensor<1, dim> normal;
    for (unsigned int d = 0; d < values.size() && d < dim; ++d)
      normal[d] = values[d];
    VPContactCheckParameter(values.size() == dim && std::isfinite(normal.norm())
                              && normal.norm() > 0,
                            "Contact/Foundation normal",
                            normal_text,
                            "give " + std::to_string(dim)
                              + " comma-separated numbers, not all zero (e.g. "
                              + (dim == 2 ? "0, -1" : "0, 0, -1")
                              + " for a foundation below the body), or leave "
                                "it empty for the body's own normal.");
    foundation = normal / normal.norm();
  }



  template <int dim>
  void
  TrescaFriction<dim>::check_iteration_constants() const
  {
    // c = factor E / h_i compares lambda with c w. The sets are the same
    // for any c > 0 only in exact arithmetic: with a factor of 1e100, the
    // round-off in w of a node that sticks makes c w larger than g, and with
    // 1e-100 the slip of a node never counts; either way the iteration
    // never settles or the matrix takes slip stiffnesses g c / (|z| - g)
    // that no solver can invert. Six orders of magnitude either side of
    // the stiffness per node leave the decisions to the physics.
    VPContactCheckParameter(
      c_factor >= 1e-6 && c_factor <= 1e6,
      "Contact/Complementarity factor",
      c_factor,
      "the factor must lie in [1e-6, 1e6], e.g. 1: c = factor x E / (the "
      "node's size) compares the friction multiplier with the "
      "stiffness times the slip, and a factor far outside this range lets "
      "round-off decide which nodes stick.");
    // A slip direction is a unit vector: its round-off is about 1e-16, and
    // two directions differ by at most 2, so a tolerance of 2 or more
    // accepts any direction and the friction law is not enforced at all.
    VPContactCheckParameter(
      bound_tol >= 1e-14 && bound_tol <= 1e-2,
      "Contact/Coulomb bound tolerance",
      bound_tol,
      "the tolerance must lie in [1e-14, 1e-2], e.g. 1e-10: Coulomb's law "
      "holds to about this fraction of the largest bound.");
    VPContactCheckParameter(
      direction_tol >= 1e-14 && direction_tol <= 1e-2,
      "Contact/Slip direction tolerance",
      direction_tol,
      "the tolerance must lie in [1e-14, 1e-2], e.g. 1e-10: the friction "
      "law holds to about this fraction of g, so a larger value leaves it "
      "unenforced, and a smaller one is below the round-off of a unit "
      "direction, which then never settles.");
  }



  namespace
  {
    // The vertices of this rank's contact faces, face by face, in one pass
    // over the cells: check_bound() evaluates the bound there at every
    // step of the run, and a pass over the mesh per step would cost the
    // cells times the steps.
    template <int dim>
    std::vector<Point<dim>>
    contact_vertices(const parallel::TriangulationBase<dim> &triangulation,
                     const std::set<types::boundary_id>     &contact_ids)
    {
      std::vector<Point<dim>> vertices;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && contact_ids.count(face->boundary_id()))
              for (const unsigned int v : face->vertex_indices())
                vertices.push_back(face->vertex(v));
      return vertices;
    }
  } // namespace



  template <int dim>
  double
  TrescaFriction<dim>::check_bound(
    const parallel::TriangulationBase<dim> &triangulation,
    const std::set<types::boundary_id>     &contact_ids,
    const std::vector<double>              &times) const
  {
    // The smallest value over the contact vertices of this rank and the
    // given times; then over all ranks, so that every rank decides alike.
    // Coulomb's law checks its coefficient instead of a bound.
    const bool           coulomb = (law == FrictionLaw::coulomb);
    FunctionParser<dim> &function
      = (coulomb ? *friction_coefficient : *friction_bound);
    const std::vector<Point<dim>> vertices
      = contact_vertices(triangulation, contact_ids);
    double     g_min = std::numeric_limits<double>::max();
    double     g_max = 0;
    Point<dim> where;
    double     when = 0;
    for (const double t : times)
      {
        function.set_time(t);
        for (const Point<dim> &vertex : vertices)
          {
            const double g = function.value(vertex);
            g_max          = std::max(g_max, g);
            // A value that is not finite counts as -infinity.
            if (std::isfinite(g) ?
                  g < g_min :
                  g_min > -std::numeric_limits<double>::infinity())
              {
                g_min = (std::isfinite(g) ?
                           g :
                           -std::numeric_limits<double>::infinity());
                where = vertex;
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
    VPContactCheckParameter(
      global_min >= 0,
      coulomb ? "Contact/Friction coefficient" : "Contact/Friction bound",
      (std::isfinite(global_min) ? to_text(global_min) :
                                   std::string("(not finite)"))
        + " at x = " + text,
      std::string("the friction ") + (coulomb ? "coefficient" : "bound")
        + " must be non-negative and finite on the "
          "contact boundary.");
    return Utilities::MPI::max(g_max, triangulation.get_communicator());
  }



  template <int dim>
  double
  TrescaFriction<dim>::bound(const Point<dim> &point, const double time) const
  {
    friction_bound->set_time(time);
    return friction_bound->value(point);
  }



  template <int dim>
  bool
  TrescaFriction<dim>::unilateral() const
  {
    return is_unilateral;
  }



  template <int dim>
  typename TrescaFriction<dim>::FrictionLaw
  TrescaFriction<dim>::friction_law() const
  {
    return law;
  }



  template <int dim>
  double
  TrescaFriction<dim>::coefficient(const Point<dim> &point,
                                   const double      time) const
  {
    friction_coefficient->set_time(time);
    return friction_coefficient->value(point);
  }



  template <int dim>
  double
  TrescaFriction<dim>::initial_gap(const Point<dim> &point,
                                   const double      time) const
  {
    gap->set_time(time);
    return gap->value(point);
  }



  template <int dim>
  const std::optional<Tensor<1, dim>> &
  TrescaFriction<dim>::foundation_normal() const
  {
    return foundation;
  }



  template <int dim>
  bool
  TrescaFriction<dim>::needs_active_set(const double largest_bound) const
  {
    return is_unilateral || largest_bound > 0;
  }



  template <int dim>
  double
  TrescaFriction<dim>::bound_tolerance() const
  {
    return bound_tol;
  }



  template <int dim>
  unsigned int
  TrescaFriction<dim>::max_iterations() const
  {
    return iteration_cap;
  }



  template <int dim>
  double
  TrescaFriction<dim>::complementarity_factor() const
  {
    return c_factor;
  }



  template <int dim>
  double
  TrescaFriction<dim>::direction_tolerance() const
  {
    return direction_tol;
  }



  template class TrescaFriction<2>;
  template class TrescaFriction<3>;
  template TrescaDecision<1>
  tresca_decision(const Tensor<1, 1> &,
                  const Tensor<1, 1> &,
                  const double,
                  const double);
  template TrescaDecision<2>
  tresca_decision(const Tensor<1, 2> &,
                  const Tensor<1, 2> &,
                  const double,
                  const double);
  template TrescaDecision<3>
  tresca_decision(const Tensor<1, 3> &,
                  const Tensor<1, 3> &,
                  const double,
                  const double);
  template double
  complementarity_constant<2>(const double, const double, const double);
  template double
  complementarity_constant<3>(const double, const double, const double);
} // namespace VPContact
