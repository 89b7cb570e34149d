// Parameter entries that hold functions of position and time.
#include <vpcontact/input_error.h>
#include <vpcontact/parsed_function.h>

#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <iostream>
#include <sstream>

namespace VPContact
{
  void
  declare_function_entry(ParameterHandler  &prm,
                         const std::string &entry,
                         const std::string &default_expression,
                         const std::string &documentation)
  {
    prm.declare_entry(entry,
                      default_expression,
                      Patterns::Anything(),
                      documentation
                        + " An expression in x, y (z in 3D) and t with one "
                          "component per coordinate direction, separated by "
                          "';' (muParser syntax).");
  }



  std::map<std::string, double>
  parse_function_constants(const ParameterHandler &prm,
                           const std::string      &entry)
  {
    std::map<std::string, double> constants;
    for (const std::string &pair : Utilities::split_string_list(prm.get(entry)))
      {
        const auto key_value    = Utilities::split_string_list(pair, ':');
        constants[key_value[0]] = Utilities::string_to_double(key_value[1]);
      }
    return constants;
  }



  std::string
  zero_expression(const unsigned int n)
  {
    std::string s = "0";
    for (unsigned int i = 1; i < n; ++i)
      s += "; 0";
    return s;
  }



  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_function_entry(const ParameterHandler              &prm,
                       const std::string                   &section,
                       const std::string                   &entry,
                       const unsigned int                   n_components,
                       const std::map<std::string, double> &constants)
  {
    const std::string              expression = prm.get(entry);
    const std::string              name       = section + "/" + entry;
    const std::vector<std::string> parts
      = Utilities::split_string_list(expression, ';');
    VPContactCheckParameter(parts.size() == n_components,
                            name,
                            "'" + expression + "'",
                            "expected " + std::to_string(n_components)
                              + " components separated by ';', found "
                              + std::to_string(parts.size()) + ".");

    const std::string variables
      = (dim == 2 ? "x,y,t" : (dim == 3 ? "x,y,z,t" : "x,t"));
    auto function = std::make_unique<FunctionParser<dim>>(n_components);
    // FunctionParser prints muParser's diagnostics to std::cerr before it
    // throws; keep them out of the screen output, our message has them.
    std::ostringstream    muparser_diagnostics;
    std::streambuf *const cerr_buffer
      = std::cerr.rdbuf(muparser_diagnostics.rdbuf());
    try
      {
        function->initialize(variables, parts, constants, true);
        // muParser compiles the expression at the first evaluation; do it
        // here so that a syntax error or an unknown variable is reported now,
        // with the parameter's name, and not in the middle of assembly.
        Vector<double> values(n_components);
        function->vector_value(Point<dim>(), values);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (const ExceptionBase &e)
      {
        std::cerr.rdbuf(cerr_buffer);
        std::ostringstream info;
        e.print_info(info);
        AssertThrow(false,
                    ExcMessage(parameter_message(
                      name,
                      "'" + expression + "'",
                      "the expression does not parse; the variables are "
                        + variables + ". muParser says:\n" + info.str())));
      }
    return function;
  }



  template std::unique_ptr<FunctionParser<2>>
  parse_function_entry<2>(const ParameterHandler &,
                          const std::string &,
                          const std::string &,
                          const unsigned int,
                          const std::map<std::string, double> &);
  template std::unique_ptr<FunctionParser<3>>
  parse_function_entry<3>(const ParameterHandler &,
                          const std::string &,
                          const std::string &,
                          const unsigned int,
                          const std::map<std::string, double> &);
} // namespace VPContact
