// The gradient damage law (2) of the paper: whether a scene has damage, its
// diffusion kappa, its source phi and its initial value, from the section
// "Damage".
#ifndef vpcontact_damage_model_h
#define vpcontact_damage_model_h

#include <vpcontact/damage/damage_source.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/thread_local_storage.h>

#include <array>
#include <memory>
#include <optional>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Damage". With "Model = gradient" the damage zeta is a second
   * field (Q1, one more component of the FESystem) solving, at each step,
   * the obstacle problem of the paper's scheme (14):
   *   ((zeta_n - zeta_{n-1})/k, xi - zeta_n) + kappa (grad zeta_n,
   *   grad(xi - zeta_n)) >= (phi_{n-1}, xi - zeta_n)  for 0 <= xi <= 1.
   * With "Model = none" there is no damage field at all (zeta = 1 in the
   * laws).
   */
  template <int dim>
  class DamageModel
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    bool
    is_active() const;

    /// kappa >= 0 [m^2/s].
    double
    diffusion() const;

    /// phi, the calling thread's copy: a muParser expression keeps its
    /// variables in the object, so each thread evaluates its own.
    const DamageSource<dim> &
    source() const;

    /// zeta_0(x), with values in [0, 1] (checked where it is used).
    const Function<dim> &
    initial_damage() const;

    /// zeta_0 where its expression is a constant (see
    /// is_constant_expression()), as in the default 1; else nothing.
    std::optional<double>
    constant_initial_damage() const;

    unsigned int
    max_iterations() const;

    /**
     * Throw a message naming Damage/Diffusion if the diffusion length
     * sqrt(kappa k) exceeds the smallest cell @p h a million times: the
     * matrix M/k + kappa A is then a Laplacian to round-off, and the damage
     * is undetermined.
     */
    void
    check_diffusion_length(const double h, const double k) const;

    /// Throw a message naming Damage/Initial damage unless @p finite.
    void
    check_initial_damage_finite(const bool finite) const;

    /// Throw a message naming Damage/Source, evaluated for step @p n at
    /// time @p t, unless @p finite.
    void
    check_source_finite(const bool         finite,
                        const unsigned int n,
                        const double       t) const;

    std::string
    description() const;

  private:
    bool                          active = false;
    double                        kappa  = 0.01;
    std::string                   source_expression;
    std::string                   initial_expression;
    std::map<std::string, double> source_constants;
    mutable Threads::ThreadLocalStorage<std::shared_ptr<DamageSource<dim>>>
                                         damage_source;
    std::unique_ptr<FunctionParser<dim>> initial;
    std::optional<double>                initial_constant;
    unsigned int                         iteration_cap = 50;
  };
} // namespace VPContact

#endif
