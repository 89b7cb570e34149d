// The contact law on the contact boundary: bilateral (the paper's) or
// unilateral contact with an initial gap, Tresca friction with the bound
// g(x, t) of the paper's condition (3) or Coulomb friction g = mu |sigma_nu|,
// the parameters of the active set iteration, and the pointwise decision
// stick/slip of the primal-dual active set method.
#ifndef vpcontact_tresca_friction_h
#define vpcontact_tresca_friction_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <memory>
#include <optional>
#include <set>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /// The state of a contact node, as written to the output (0, 1, 2).
  enum class ContactStatus
  {
    none      = 0,
    stick     = 1,
    slip      = 2,
    separated = 3
  };

  /**
   * A node's next state: stick, or slip in the unit direction n of
   * lambda + c w in the tangent plane, with the slip stiffness beta of the
   * linearised slip law lambda = g n + beta (I - n n^T) w.
   */
  template <int dim>
  struct TrescaDecision
  {
    ContactStatus  status;
    Tensor<1, dim> direction;          // n for slip, 0 for stick
    double         slip_stiffness = 0; // beta for slip, 0 for stick
  };

  /**
   * The primal-dual active set (semismooth Newton) decision for one contact
   * node of Tresca's law in the tangent plane (Hueber, Stadler and
   * Wohlmuth). With lambda the nodal friction multiplier (lambda =
   * -sigma_tau, the residual per unit boundary measure), w the tangential
   * slip and c > 0, the discrete conditions |lambda| <= g and
   * lambda . w = g |w| are equivalent to
   *   max(g, |lambda + c w|) lambda = g (lambda + c w).
   * The node sticks (w = 0) where |lambda + c w| <= g, and slips
   * elsewhere. A slip node's law lambda = g w / |w| is nonlinear in w; its
   * Newton linearisation about z = lambda + c w, n = z / |z|, with lambda
   * taken parallel to n, is lambda = g n + beta (I - n n^T) w with
   * beta = g c / (|z| - g) > 0: the node resists slip across n, not along
   * it. In 2D the tangent plane is a line, I - n n^T vanishes on it and
   * the decision is the sign switch lambda = g sign(lambda + c w).
   */
  template <int dim>
  TrescaDecision<dim>
  tresca_decision(const Tensor<1, dim> &lambda,
                  const Tensor<1, dim> &slip,
                  const double          g,
                  const double          c);

  /**
   * The constant c of tresca_decision() at a contact node of lumped
   * boundary measure @p measure (a length in 2D, an area in 3D):
   * c = @p factor E / h with the node's size h = m_i in 2D and sqrt(m_i)
   * in 3D. E / h is the stiffness per node over its measure, so that c w
   * is a traction like lambda. E / m_i in 3D would grow like 1/h^2: on
   * fine meshes the slip stiffness g c / (|lambda + c w| - g) of the nodes
   * that barely slip would dwarf the body's, CG would need many times the
   * iterations, and the stick/slip iteration would stop settling.
   */
  template <int dim>
  double
  complementarity_constant(const double factor,
                           const double youngs_modulus,
                           const double measure);

  /**
   * Section "Contact": the normal condition (bilateral u.nu = 0, or
   * unilateral u.nu <= g_0 with the foundation's normal nu and the initial
   * gap g_0(x, t)), the friction law (Tresca with the bound g(x, t) >= 0,
   * or Coulomb with g = mu(x) |sigma_nu|) on Gamma_C, and the controls of
   * the active set iteration.
   */
  template <int dim>
  class TrescaFriction
  {
  public:
    enum class FrictionLaw
    {
      tresca,
      coulomb
    };

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Stop with a message naming Contact/Friction bound (Coulomb: Friction
     * coefficient) if g < 0 (mu < 0) or not finite at a vertex of the faces
     * with @p contact_ids at one of the @p times. Returns the largest value
     * found there (0: frictionless).
     */
    double
    check_bound(const parallel::TriangulationBase<dim> &triangulation,
                const std::set<types::boundary_id>     &contact_ids,
                const std::vector<double>              &times) const;

    /// g(x, t) (Tresca).
    double
    bound(const Point<dim> &point, const double time) const;

    /// Whether the normal condition is unilateral (Signorini).
    bool
    unilateral() const;

    FrictionLaw
    friction_law() const;

    /// mu(x, t) (Coulomb).
    double
    coefficient(const Point<dim> &point, const double time) const;

    /// g_0(x, t): the distance from the body to the foundation along nu at
    /// the start (unilateral).
    double
    initial_gap(const Point<dim> &point, const double time) const;

    /// The foundation's unit normal (pointing from the body into the
    /// foundation) if the scene gives one; otherwise each node takes the
    /// body's outward normal.
    const std::optional<Tensor<1, dim>> &
    foundation_normal() const;

    /// Whether the contact boundary needs an active set at all: unilateral
    /// contact, or friction somewhere (@p g_max, the largest Tresca bound,
    /// or the largest Coulomb coefficient on the contact boundary > 0).
    bool
    needs_active_set(const double largest_bound) const;

    /// How far the Coulomb bounds may move, relative to the largest, in a
    /// converged iteration.
    double
    bound_tolerance() const;

    unsigned int
    max_iterations() const;

    /// The factor of the complementarity constant c (see FrictionActiveSet).
    double
    complementarity_factor() const;

    /// How far a slip direction may turn in a converged iteration.
    double
    direction_tolerance() const;

  private:
    /// Refuse a complementarity factor or slip direction tolerance outside
    /// the range where the iteration's decisions are not round-off.
    void
    check_iteration_constants() const;

    /// Declare the entries of the normal condition and of Coulomb's law.
    static void
    declare_law_parameters(ParameterHandler &prm);

    /// Read the entries of the unilateral condition and of Coulomb's law.
    void
    parse_law(ParameterHandler &prm);

    std::unique_ptr<FunctionParser<dim>> friction_bound;
    std::unique_ptr<FunctionParser<dim>> friction_coefficient;
    std::unique_ptr<FunctionParser<dim>> gap;
    std::optional<Tensor<1, dim>>        foundation;
    bool                                 is_unilateral = false;
    FrictionLaw                          law           = FrictionLaw::tresca;
    double                               bound_tol     = 1e-10;
    unsigned int                         iteration_cap = 50;
    double                               c_factor      = 1.;
    double                               direction_tol = 1e-10;
  };
} // namespace VPContact

#endif
