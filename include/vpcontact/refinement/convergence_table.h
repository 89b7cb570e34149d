// The convergence table of a sequence of runs: mesh, step, run time and the
// errors of Theorem 2 of each run, with the observed orders.
#ifndef vpcontact_convergence_table_h
#define vpcontact_convergence_table_h

#include <vpcontact/postprocess/reference_solution.h>
#include <vpcontact/refinement/error_estimator.h>

#include <string>
#include <vector>

namespace VPContact
{
  /**
   * One row per run (refinement cycle). The observed order of an error e
   * against the previous row is log(e_prev / e) / log(h_prev / h), with h
   * the equivalent mesh size (|Omega| / cells)^(1/dim): for uniform
   * refinement the usual order in h, for adaptive meshes the order in
   * (number of cells)^(-1/dim), which makes the two comparable. With k
   * refined with h, an O(h + k) method shows order 1. The orders are
   * deal.II's ConvergenceTable::reduction_rate_log2 against 1/h.
   */
  class ConvergenceTable
  {
  public:
    struct Row
    {
      unsigned int       cycle = 0;
      unsigned long long cells = 0;
      unsigned long long dofs  = 0;
      double             h     = 0;
      double             k     = 0;
      unsigned int       steps = 0;
      /// The run's wall time [s] (setup, steps, indicators and output; not
      /// the comparison with the reference), and the sum over the cycles
      /// so far (what an adaptive mesh costs to find).
      double wall_time            = 0;
      double cumulative_wall_time = 0;
      bool   has_errors           = false;
      /// max over the common times, and at the final time.
      ErrorNorms max_error;
      /// max over the common times of the summed error (Theorem 2's norm).
      double     max_error_sum = 0;
      ErrorNorms final_error;
      /// The number of common times the maximum was taken over.
      unsigned int compared_times = 0;
      /// The run's error estimate: the one whose sum is the largest over
      /// the steps, and the largest of each part on its own.
      bool          has_estimate = false;
      ErrorEstimate estimate, estimate_parts;
      /// estimate.sum() / max_error_sum (NaN without errors or estimate).
      double
      effectivity() const;
    };

    void
    add_row(const Row &row);
    const std::vector<Row> &
    rows() const;

    /// The table as CSV (one header line), orders included.
    std::string
    to_csv() const;
    /// The table for the screen: the max-over-time errors and their orders,
    /// with the wall time if @p with_times.
    std::string
    to_text(const bool with_times) const;

  private:
    std::vector<Row> table;
  };

} // namespace VPContact

#endif
