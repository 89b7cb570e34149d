// The start vector of a time step's displacement solve: the increments of
// the previous steps extrapolated to the new one.
#ifndef vpcontact_increment_predictor_h
#define vpcontact_increment_predictor_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>

namespace VPContact
{
  using namespace dealii;

  /**
   * In a quasistatic run under a smooth load the displacement increments
   * w_{n-1}, w_{n-2}, ... of consecutive steps of equal length lie on a
   * smooth curve, and the polynomial of degree p through the last p + 1 of
   * them predicts w_n with an error of order k^{p+1}. CG needs about as
   * many iterations as the residual of its start vector must fall decades
   * to reach the tolerance, so a better start vector saves iterations in
   * every step: the linear extrapolation is 2 w_{n-1} - w_{n-2}, the
   * quadratic one 3 w_{n-1} - 3 w_{n-2} + w_{n-3}.
   *
   * Only the start vector changes: the solution is the same to the solver
   * tolerance. Until enough steps are recorded (after setup, on a new mesh,
   * after a jump, see record()) the degree is lowered to what the history
   * allows.
   */
  class IncrementPredictor
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /// Forget the recorded increments and size the vectors (new mesh).
    void
    reinit(const IndexSet &locally_owned_dofs, const MPI_Comm communicator);

    /// Overwrite @p increment, which holds w_{n-1}, with the prediction of
    /// w_n.
    void
    predict(LA::MPI::Vector &increment) const;

    /// Record the increment of the step just solved; one more than
    /// jump_ratio times larger or smaller than the last restarts the
    /// history.
    void
    record(const LA::MPI::Vector &increment);

    /// For checkpoints: the number of increments recorded (at most 3)...
    unsigned int
    n_recorded() const;

    /// ... and w_{n-1 - i}, i = 0, 1, 2 (read, or restored from a
    /// checkpoint together with set_n_recorded()).
    LA::MPI::Vector &
    recorded(const unsigned int i);

    void
    set_n_recorded(const unsigned int n);

  private:
    static constexpr double        jump_ratio = 10.;
    unsigned int                   degree     = 2;
    unsigned int                   n_valid    = 0;
    std::array<LA::MPI::Vector, 3> history;
  };
} // namespace VPContact

#endif
