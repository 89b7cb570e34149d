// The damage source phi: a muParser expression in the local state.
#include <vpcontact/damage/damage_source.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/material/stress_measures.h>

#include <muParser.h>

namespace VPContact
{
  namespace
  {
    // The variable names in the order of DamageSource::variables.
    template <int dim>
    std::vector<std::string>
    names()
    {
      std::vector<std::string> components
        = (dim == 2 ?
             std::vector<std::string>{"xx", "yy", "xy"} :
             std::vector<std::string>{"xx", "yy", "zz", "xy", "xz", "yz"});
      std::vector<std::string> result = {"zeta"};
      for (const auto &c : components)
        result.push_back("eps_" + c);
      for (const auto &c : components)
        result.push_back("sigma_" + c);
      for (const std::string n : {"eps_eps", "energy", "von_mises", "x", "y"})
        result.push_back(n);
      if (dim == 3)
        result.push_back("z");
      result.push_back("t");
      return result;
    }
  } // namespace



  template <int dim>
  DamageSource<dim>::DamageSource(
    const std::string                   &expression,
    const std::map<std::string, double> &constants,
    const std::string                   &parameter_name)
    : parser(std::make_unique<mu::Parser>())
    , values(names<dim>().size(), 0.)
  {
    try
      {
        const auto variable_list = names<dim>();
        for (unsigned int i = 0; i < variable_list.size(); ++i)
          parser->DefineVar(variable_list[i], &values[i]);
        for (const auto &[name, value] : constants)
          parser->DefineConst(name, value);
        parser->SetExpr(expression);
        parser->Eval(); // compiles the expression: report errors now
      }
    catch (const mu::Parser::exception_type &e)
      {
        AssertThrow(false,
                    ExcMessage(parameter_message(
                      parameter_name,
                      "'" + expression + "'",
                      "the expression does not parse (" + e.GetMsg()
                        + "). The variables are " + variable_names()
                        + ", and the constants of 'Function constants'.")));
      }
  }



  template <int dim>
  DamageSource<dim>::~DamageSource() = default;



  template <int dim>
  double
  DamageSource<dim>::value(const SymmetricTensor<2, dim> &strain,
                           const SymmetricTensor<2, dim> &stress,
                           const double                   zeta,
                           const Point<dim>              &point,
                           const double                   time) const
  {
    constexpr unsigned int n
      = SymmetricTensor<2, dim>::n_independent_components;
    unsigned int i = 0;
    values[i++]    = zeta;
    for (unsigned int c = 0; c < n; ++c)
      values[i++] = strain.access_raw_entry(c);
    for (unsigned int c = 0; c < n; ++c)
      values[i++] = stress.access_raw_entry(c);
    values[i++] = strain * strain;
    values[i++] = 0.5 * (stress * strain);
    values[i++] = von_mises_norm(stress);
    for (unsigned int d = 0; d < dim; ++d)
      values[i++] = point[d];
    values[i++] = time;
    return parser->Eval();
  }



  template <int dim>
  std::string
  DamageSource<dim>::variable_names()
  {
    std::string text;
    for (const auto &name : names<dim>())
      text += (text.empty() ? "" : ", ") + name;
    return text;
  }



  template <int dim>
  std::vector<std::string>
  DamageSource<dim>::variables()
  {
    return names<dim>();
  }



  template class DamageSource<2>;
  template class DamageSource<3>;
} // namespace VPContact
