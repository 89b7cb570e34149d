// Tresca friction on the contact boundary: the friction bound g(x, t) of the
// paper's condition (3), the parameters of the active set iteration, and the
// pointwise decision stick/slip of the primal-dual active set method.
#ifndef vpcontact_tresca_friction_h
#define vpcontact_tresca_friction_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <memory>
#include <set>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /// The state of a contact node, as written to the output (0, 1, 2).
  enum class ContactStatus
  {
    none  = 0,
    stick = 1,
    slip  = 2
  };

  /// A node's next state: stick, or slip with the direction of lambda.
  struct TrescaDecision
  {
    ContactStatus status;
    double        direction; // +1 or -1 for slip, 0 for stick
  };

  /**
   * The primal-dual active set (semismooth Newton) decision for one contact
   * node of a 2D Tresca problem. With lambda the nodal friction multiplier
   * (lambda = -sigma_tau, the residual per unit boundary length), w the
   * tangential slip and c > 0, the discrete conditions |lambda| <= g and
   * lambda w = g |w| are equivalent to
   *   max(g, |lambda + c w|) lambda = g (lambda + c w).
   * The node sticks (w = 0) where |lambda + c w| <= g, and slips with
   * lambda = g sign(lambda + c w) elsewhere.
   */
  TrescaDecision
  tresca_decision(const double lambda,
                  const double slip,
                  const double g,
                  const double c);

  /**
   * Section "Contact": the friction bound g(x, t) >= 0 on Gamma_C and the
   * controls of the active set iteration.
   */
  template <int dim>
  class TrescaFriction
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Stop with a message naming Contact/Friction bound if g < 0 (or not
     * finite) at a vertex of the faces with @p contact_ids at one of the
     * @p times. Returns the largest g found there (0: frictionless).
     */
    double
    check_bound(const parallel::distributed::Triangulation<dim> &triangulation,
                const std::set<types::boundary_id>              &contact_ids,
                const std::vector<double>                       &times) const;

    /// g(x, t).
    double
    bound(const Point<dim> &point, const double time) const;

    unsigned int
    max_iterations() const;

    /// The factor of the complementarity constant c (see FrictionActiveSet).
    double
    complementarity_factor() const;

  private:
    std::unique_ptr<FunctionParser<dim>> friction_bound;
    unsigned int                         iteration_cap = 50;
    double                               c_factor      = 1.;
  };
} // namespace VPContact

#endif
