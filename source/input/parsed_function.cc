// Parameter entries that hold functions of position and time.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parsed_function.h>

#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <muParser.h>
#include <regex>
#include <set>
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



  namespace
  {
    // Names that muParser and deal.II's FunctionParser give a meaning of
    // their own: functions and built-in constants. A constant of the same
    // name would hide them or be refused by muParser with an exception.
    const std::set<std::string> &
    reserved_names()
    {
      static const std::set<std::string> names
        = {"sin",       "cos",   "tan",   "asin",  "acos",  "atan", "sinh",
           "cosh",      "tanh",  "asinh", "acosh", "atanh", "log2", "log10",
           "log",       "ln",    "exp",   "sqrt",  "sign",  "rint", "abs",
           "min",       "max",   "sum",   "avg",   "if",    "int",  "ceil",
           "floor",     "cot",   "csc",   "sec",   "pow",   "erfc", "rand",
           "rand_seed", "atan2", "fmod",  "_pi",   "_e"};
      return names;
    }

    // A name as muParser reads one: a letter or '_', then letters, digits
    // and '_'.
    bool
    is_identifier(const std::string &name)
    {
      if (name.empty()
          || !(std::isalpha(static_cast<unsigned char>(name[0]))
               || name[0] == '_'))
        return false;
      for (const char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
          return false;
      return true;
    }
  } // namespace



  std::map<std::string, double>
  parse_function_constants(const ParameterHandler         &prm,
                           const std::string              &section,
                           const std::string              &entry,
                           const std::vector<std::string> &variables)
  {
    const std::string name  = section + "/" + entry;
    const std::string value = prm.get(entry);
    std::string       variable_list;
    for (const auto &v : variables)
      variable_list += (variable_list.empty() ? "" : ", ") + v;

    std::map<std::string, double> constants;
    for (const std::string &pair : Utilities::split_string_list(value))
      {
        const auto key_value = Utilities::split_string_list(pair, ':');
        VPContactCheckParameter(key_value.size() == 2,
                                name,
                                value,
                                "'" + pair
                                  + "' is not a pair name:value. Write the "
                                    "constants as 'a:1, b:2'.");
        const std::string &constant = key_value[0];
        VPContactCheckParameter(is_identifier(constant),
                                name,
                                value,
                                "'" + constant
                                  + "' is not a name: a constant's name "
                                    "starts with a letter or '_' and holds "
                                    "only letters, digits and '_'.");
        VPContactCheckParameter(
          std::find(variables.begin(), variables.end(), constant)
            == variables.end(),
          name,
          value,
          "'" + constant
            + "' is a variable of the expressions of this "
              "section ("
            + variable_list
            + "); a constant cannot take its place. Choose another name.");
        VPContactCheckParameter(reserved_names().count(constant) == 0,
                                name,
                                value,
                                "'" + constant
                                  + "' is the name of a built-in function or "
                                    "constant of the expressions. Choose "
                                    "another name.");
        VPContactCheckParameter(constants.count(constant) == 0,
                                name,
                                value,
                                "the constant '" + constant
                                  + "' is given twice. Give it once.");
        constants[constant] = Utilities::string_to_double(key_value[1]);
      }
    return constants;
  }



  std::vector<std::string>
  coordinate_variables(const unsigned int dim)
  {
    return (dim == 2 ? std::vector<std::string>{"x", "y", "t"} :
                       std::vector<std::string>{"x", "y", "z", "t"});
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
    return parse_function_expression<dim>(prm.get(entry),
                                          section + "/" + entry,
                                          n_components,
                                          constants);
  }



  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_function_expression(const std::string                   &expression,
                            const std::string                   &name,
                            const unsigned int                   n_components,
                            const std::map<std::string, double> &constants)
  {
    const std::vector<std::string> parts
      = Utilities::split_string_list(expression, ';');
    VPContactCheckParameter(parts.size() == n_components,
                            name,
                            "'" + expression + "'",
                            "expected " + std::to_string(n_components)
                              + " components separated by ';', found "
                              + std::to_string(parts.size()) + ".");

    // rand() gives another value in every evaluation, on every rank and
    // after a resume: a result that cannot be reproduced.
    static const std::regex random("(^|[^A-Za-z0-9_])rand(_seed)? *\\(");
    VPContactCheckParameter(!std::regex_search(expression, random),
                            name,
                            "'" + expression + "'",
                            "rand() makes the run irreproducible (other "
                            "values on every rank, in every step and after "
                            "a resume). Give a deterministic expression.");
    const std::string variables
      = (dim == 2 ? "x,y,t" : (dim == 3 ? "x,y,z,t" : "x,t"));
    auto function = std::make_unique<FunctionParser<dim>>(n_components);
    // FunctionParser prints muParser's diagnostics to std::cerr before it
    // throws; keep them out of the screen output, our message has them.
    std::ostringstream    muparser_diagnostics;
    std::streambuf *const cerr_buffer
      = std::cerr.rdbuf(muparser_diagnostics.rdbuf());
    std::string problem;
    try
      {
        function->initialize(variables, parts, constants, true);
        // muParser compiles the expression at the first evaluation; do it
        // here so that a syntax error or an unknown variable is reported now,
        // with the parameter's name, and not in the middle of assembly.
        Vector<double> values(n_components);
        function->vector_value(Point<dim>(), values);
      }
    catch (const ExceptionBase &e)
      {
        problem = error_message(e);
      }
    // muParser's own exceptions are not std::exceptions.
    catch (const mu::Parser::exception_type &e)
      {
        problem = e.GetMsg();
      }
    std::cerr.rdbuf(cerr_buffer);
    VPContactCheckParameter(problem.empty(),
                            name,
                            "'" + expression + "'",
                            "the expression does not parse; the variables are "
                              + variables + ". muParser says:\n" + problem);
    return function;
  }



  std::vector<std::string>
  split_outside_parentheses(const std::string &text)
  {
    std::vector<std::string> parts(1);
    int                      depth = 0;
    for (const char c : text)
      {
        depth += (c == '(') - (c == ')');
        if (c == ',' && depth == 0)
          parts.emplace_back();
        else
          parts.back() += c;
      }
    for (auto &part : parts)
      part = Utilities::trim(part);
    if (parts.size() == 1 && parts[0].empty())
      parts.clear();
    return parts;
  }



  bool
  is_constant_expression(const std::string              &expression,
                         const std::vector<std::string> &variables)
  {
    // The numbers (with their exponents, as in 1e-3) and the names of the
    // text in turn: a name must be neither a variable nor a function's,
    // i.e. followed by '('.
    static const std::regex token(
      "(?:[0-9]+\\.?[0-9]*|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
      "|([A-Za-z_][A-Za-z0-9_]*)(\\s*\\()?");
    for (auto match
         = std::sregex_iterator(expression.begin(), expression.end(), token);
         match != std::sregex_iterator();
         ++match)
      if ((*match)[1].matched
          && ((*match)[2].matched
              || std::find(variables.begin(),
                           variables.end(),
                           (*match)[1].str())
                   != variables.end()))
        return false;
    return true;
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
  template std::unique_ptr<FunctionParser<2>>
  parse_function_expression<2>(const std::string &,
                               const std::string &,
                               const unsigned int,
                               const std::map<std::string, double> &);
  template std::unique_ptr<FunctionParser<3>>
  parse_function_expression<3>(const std::string &,
                               const std::string &,
                               const unsigned int,
                               const std::map<std::string, double> &);
} // namespace VPContact
