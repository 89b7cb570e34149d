// BoundaryFunctions: "id: expression" lists of boundary functions.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parsed_function.h>
#include <vpcontact/problem_data/boundary_functions.h>

#include <deal.II/base/utilities.h>

#include <vector>

namespace VPContact
{



  template <int dim>
  void
  BoundaryFunctions<dim>::parse(const std::string                   &text,
                                const std::string                   &name,
                                const std::map<std::string, double> &constants)
  {
    functions.clear();
    for (const std::string &pair : split_outside_parentheses(text))
      {
        const auto colon = pair.find(':');
        VPContactCheckParameter(colon != std::string::npos,
                                name,
                                pair,
                                "expected 'id: expression' pairs separated "
                                "by commas, e.g. '1: 55*exp(t); 0, 3: 0; "
                                "-200'.");
        const std::string id_text = Utilities::trim(pair.substr(0, colon));
        int               id      = -1;
        try
          {
            id = Utilities::string_to_int(id_text);
          }
        catch (...)
          {}
        VPContactCheckParameter(id >= 0 && id <= 254,
                                name,
                                pair,
                                "'" + id_text
                                  + "' is no boundary id (an integer in [0, "
                                    "254]).");
        const auto [it, inserted]
          = functions.emplace(id,
                              parse_function_expression<dim>(
                                Utilities::trim(pair.substr(colon + 1)),
                                name + ", boundary id " + id_text,
                                dim,
                                constants));
        VPContactCheckParameter(inserted,
                                name,
                                text,
                                "boundary id " + id_text + " is listed twice.");
      }
  }



  template <int dim>
  std::set<types::boundary_id>
  BoundaryFunctions<dim>::ids() const
  {
    std::set<types::boundary_id> result;
    for (const auto &[id, function] : functions)
      result.insert(id);
    return result;
  }



  template <int dim>
  bool
  BoundaryFunctions<dim>::has(const types::boundary_id id) const
  {
    return functions.count(id) == 1;
  }



  template <int dim>
  const Function<dim> &
  BoundaryFunctions<dim>::function(const types::boundary_id id) const
  {
    return *functions.at(id);
  }



  template <int dim>
  void
  BoundaryFunctions<dim>::set_time(const double time)
  {
    for (auto &[id, function] : functions)
      function->set_time(time);
  }



  template class BoundaryFunctions<2>;
  template class BoundaryFunctions<3>;
} // namespace VPContact
