// Comparison of the computed displacement with a displacement known in closed
// form, for scenes whose exact solution is known (e.g. elastic_bar).
#ifndef vpcontact_verification_h
#define vpcontact_verification_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <map>
#include <memory>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Verification". When "Exact displacement" is given, every step
   * reports the largest nodal error max_i |u_h(x_i) - u(x_i)| and the L2
   * error ||u_h - u||, which are round-off for a solution in the finite
   * element space. When "Exact stress" is given, every step reports the
   * largest error of the quadrature point stress; "Exact damage", the
   * largest nodal error of the damage.
   */
  template <int dim>
  class Verification
  {
  public:
    struct Errors
    {
      double max_nodal = 0;
      double l2        = 0;
    };

    static void
    declare_parameters(ParameterHandler &prm);

    /// @p n_components: of the finite element (dim, or dim + 1 with damage).
    void
    parse_parameters(ParameterHandler &prm, const unsigned int n_components);

    /// Whether an exact displacement is given.
    bool
    is_active() const;

    /// Whether an exact damage is given.
    bool
    has_exact_damage() const;

    /**
     * max_i |zeta_h(x_i) - zeta(x_i, time)| over the damage nodes (the
     * last component of @p dof_handler's element) of all ranks; the
     * largest is kept for summary().
     */
    double
    damage_error(const DoFHandler<dim> &dof_handler,
                 const LA::MPI::Vector &solution,
                 const double           time);

    /// Whether an exact stress is given.
    bool
    has_exact_stress() const;

    /// The exact stress at @p point and @p time.
    SymmetricTensor<2, dim>
    exact_stress(const Point<dim> &point, const double time) const;

    /// Keep the largest stress error of the run for summary().
    void
    record_stress_error(const double error, const double stress_scale);

    /**
     * The errors of the ghosted displacement @p solution at @p time, whose
     * largest nodal value is @p u_max; the run's largest errors are kept
     * for summary().
     */
    Errors
    compute_errors(const DoFHandler<dim> &dof_handler,
                   const LA::MPI::Vector &solution,
                   const double           time,
                   const double           u_max);

    /**
     * One line for the end of the run: the largest nodal error relative to
     * the largest displacement, and whether that is round-off.
     */
    std::string
    summary() const;

    /// The largest errors so far, by name, that summary() reports (for
    /// checkpoints), and their restoration in a resumed run.
    std::map<std::string, double>
    running_maxima() const;

    void
    restore_running_maxima(const std::map<std::string, double> &maxima);

  private:
    /// A relative nodal error below this is round-off for double precision
    /// and the solver tolerances the verification scenes use.
    static constexpr double round_off_level = 1e-10;

    double max_nodal_error  = 0;
    double max_displacement = 0;

    std::unique_ptr<FunctionParser<dim>> exact_displacement;
    std::unique_ptr<FunctionParser<dim>> exact_stress_function;
    std::unique_ptr<FunctionParser<dim>> exact_damage;
    unsigned int                         n_fe_components  = dim;
    double                               max_damage_error = 0;
    double                               max_stress_error = 0;
    double                               max_stress       = 0;
  };
} // namespace VPContact

#endif
