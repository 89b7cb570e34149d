// The uniform time grid t_n = n k, n = 0..N, k = T/N of the paper's scheme.
#ifndef vpcontact_time_discretization_h
#define vpcontact_time_discretization_h

#include <deal.II/base/parameter_handler.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Time": the end time T and the step k. The paper's scheme uses a
   * uniform partition, so T must be a whole number of steps.
   */
  class TimeDiscretization
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    double
    end_time() const;

    double
    step_size() const;

    unsigned int
    n_steps() const;

    /// t_n = n k (exactly T for n = N).
    double
    time(const unsigned int n) const;

    /**
     * Use the step of the parameter file halved @p j times (k / 2^j,
     * N 2^j steps): the time grid of a refinement cycle. j = 0 restores it.
     */
    void
    set_halvings(const unsigned int j);

  private:
    double       T       = 1.;
    double       k       = 0.01;
    unsigned int n_total = 100;
    /// The step and number of steps of the parameter file.
    double       k_given = 0.01;
    unsigned int n_given = 100;
  };
} // namespace VPContact

#endif
