// Tresca friction on the contact boundary: the friction bound g(x, t) of the
// paper's condition (3) and functional j of (8).
#ifndef vpcontact_tresca_friction_h
#define vpcontact_tresca_friction_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <memory>
#include <set>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Contact": the friction bound g >= 0 on Gamma_C.
   *
   * In this release the bound is read and checked (g >= 0 at every contact
   * vertex and every step time), but the contact boundary is a frictionless
   * bilateral support: the primal-dual active set for the friction
   * conditions is the next development step (issue 4). The screen output
   * says so whenever a scene has a contact boundary.
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
     * @p times.
     */
    void
    check_bound(const parallel::distributed::Triangulation<dim> &triangulation,
                const std::set<types::boundary_id>              &contact_ids,
                const std::vector<double>                       &times) const;

  private:
    std::unique_ptr<FunctionParser<dim>> friction_bound;
  };
} // namespace VPContact

#endif
