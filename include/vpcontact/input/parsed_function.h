// Building a FunctionParser from a parameter entry, so that an expression
// that does not parse is reported with the parameter's name.
#ifndef vpcontact_parsed_function_h
#define vpcontact_parsed_function_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Declare an entry holding a function of x, y (, z) and t with
   * @p n_components components separated by ';'.
   */
  void
  declare_function_entry(ParameterHandler  &prm,
                         const std::string &entry,
                         const std::string &default_expression,
                         const std::string &documentation);

  /**
   * The parsed function of the entry @p entry of the current subsection
   * (called @p section in messages). @p constants are name=value pairs that
   * the expression may use. Throws an ExcMessage naming the parameter when
   * the expression does not parse or has the wrong number of components.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_function_entry(const ParameterHandler              &prm,
                       const std::string                   &section,
                       const std::string                   &entry,
                       const unsigned int                   n_components,
                       const std::map<std::string, double> &constants = {});

  /**
   * The parsed function of @p expression, called @p name in messages (e.g.
   * "Boundary conditions/Tractions, id 3"), as parse_function_entry().
   */
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_function_expression(const std::string                   &expression,
                            const std::string                   &name,
                            const unsigned int                   n_components,
                            const std::map<std::string, double> &constants);

  /**
   * The named constants of the entry @p entry of the current subsection
   * (called @p section in messages), written as name:value pairs ("p:55,
   * E:1000"), for the expressions of that subsection, whose variables are
   * @p variables. Throws a message naming the entry if a name is not an
   * identifier, is one of @p variables or a built-in function of the
   * expressions, or is given twice.
   */
  std::map<std::string, double>
  parse_function_constants(const ParameterHandler         &prm,
                           const std::string              &section,
                           const std::string              &entry,
                           const std::vector<std::string> &variables);

  /// The parts of @p text between the commas outside parentheses, trimmed
  /// ("1: max(x, 0); 0, 2: 0; 1" is two parts); none for an empty text.
  std::vector<std::string>
  split_outside_parentheses(const std::string &text);

  /**
   * Whether the expression @p expression, which has parsed, is a constant:
   * it names none of @p variables and calls no function (not even one of
   * constant arguments such as sqrt(2), nor rand()). Its named constants
   * and numbers are what is left. Then its value is the same at every
   * point, and a field interpolated from it needs no evaluation per node.
   */
  bool
  is_constant_expression(const std::string              &expression,
                         const std::vector<std::string> &variables);

  /// The variables of a function of position and time: x, y (z), t.
  std::vector<std::string>
  coordinate_variables(const unsigned int dim);

  /**
   * A function with dim components (a displacement) seen as a function with
   * @p n_components components, zero beyond the first dim, to be used with
   * a finite element that has more components (the damage).
   */
  template <int dim>
  class DisplacementFunction : public Function<dim>
  {
  public:
    DisplacementFunction(const Function<dim> &displacement,
                         const unsigned int   n_components)
      : Function<dim>(n_components)
      , displacement(displacement)
    {}

    double
    value(const Point<dim> &p, const unsigned int component) const override
    {
      return component < dim ? displacement.value(p, component) : 0.;
    }

  private:
    const Function<dim> &displacement;
  };

  /// The zero expression with @p n components: "0; 0" for n = 2.
  std::string
  zero_expression(const unsigned int n);
} // namespace VPContact

#endif
