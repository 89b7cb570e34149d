// Boundary ids with a function each, written as ASPECT writes its
// "indicator: function" lists ("1: 55*exp(t); 0, 3: 0; -200"): the tractions
// of several loaded faces, each its own function of x and t.
#ifndef vpcontact_boundary_functions_h
#define vpcontact_boundary_functions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/types.h>

#include <map>
#include <memory>
#include <set>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * A map from boundary ids to vector-valued functions of x and t with dim
   * components, read from one parameter entry.
   */
  template <int dim>
  class BoundaryFunctions
  {
  public:
    /**
     * Read @p text, the value of the entry @p name: "id: expression" pairs
     * separated by commas outside parentheses (so that max(a, b) stays one
     * expression), each expression with dim components separated by ';'.
     * Refuses, naming @p name, a pair without ':', an id that is no integer
     * in [0, 254] or is listed twice, and an expression that does not
     * parse. @p constants are the named constants the expressions may use.
     */
    void
    parse(const std::string                   &text,
          const std::string                   &name,
          const std::map<std::string, double> &constants);

    /// The boundary ids listed.
    std::set<types::boundary_id>
    ids() const;

    bool
    has(const types::boundary_id id) const;

    /// The function of @p id, at the time last given to set_time().
    const Function<dim> &
    function(const types::boundary_id id) const;

    void
    set_time(const double time);

  private:
    std::map<types::boundary_id, std::unique_ptr<FunctionParser<dim>>>
      functions;
  };
} // namespace VPContact

#endif
