// The damage source function phi(sigma, eps(u), zeta) of the damage law (2),
// parsed from an expression in named variables of the local state.
#ifndef vpcontact_damage_source_h
#define vpcontact_damage_source_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mu
{
  class Parser;
}

namespace VPContact
{
  using namespace dealii;

  /**
   * phi as a muParser expression. The variables are
   * - zeta: the damage;
   * - eps_xx, eps_yy, eps_xy (3D also eps_zz, eps_xz, eps_yz): the strain;
   * - sigma_xx, ... likewise: the stress;
   * - eps_eps = eps : eps, energy = 1/2 sigma : eps (the strain energy
   *   density), von_mises (the von Mises norm of sigma);
   * - x, y (z), t;
   * and any named constants. No finite element types: a function of the
   * local state, unit-tested against closed forms.
   */
  template <int dim>
  class DamageSource
  {
  public:
    /**
     * Parse @p expression. Throws an ExcMessage naming @p parameter_name
     * and the known variables if it does not parse or uses an unknown name.
     */
    DamageSource(const std::string                   &expression,
                 const std::map<std::string, double> &constants,
                 const std::string                   &parameter_name);
    ~DamageSource();

    double
    value(const SymmetricTensor<2, dim> &strain,
          const SymmetricTensor<2, dim> &stress,
          const double                   zeta,
          const Point<dim>              &point,
          const double                   time) const;

    /// The names of the variables, for messages and documentation.
    static std::string
    variable_names();

    /// The names of the variables, one by one.
    static std::vector<std::string>
    variables();

  private:
    std::unique_ptr<mu::Parser> parser;
    /// The values the parser reads, by variable (muParser keeps pointers).
    mutable std::vector<double> values;
  };
} // namespace VPContact

#endif
