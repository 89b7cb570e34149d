// The convergence study of a run: its refinement cycles, the snapshots and
// errors against a reference run, and the convergence table.
#ifndef vpcontact_convergence_study_h
#define vpcontact_convergence_study_h

#include <vpcontact/postprocess/reference_solution.h>
#include <vpcontact/postprocess/statistics.h>
#include <vpcontact/refinement/convergence_table.h>
#include <vpcontact/refinement/error_estimator.h>
#include <vpcontact/refinement/mesh_refinement.h>
#include <vpcontact/simulator/time_discretization.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <functional>
#include <set>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Everything a run does across its refinement cycles, apart from the run
   * of a cycle itself: the mesh of the next cycle (MeshRefinement, from the
   * ErrorEstimator's cell indicators of a cycle), the time step of each cycle,
   * the snapshots written for a later comparison and the errors of Theorem
   * 2 against a reference run (ReferenceSolution), and the ConvergenceTable
   * with the run time of each cycle. See doc/convergence.md.
   */
  template <int dim>
  class ConvergenceStudy
  {
  public:
    /// Sections "Mesh refinement" and "Reference solution".
    static void
    declare_parameters(ParameterHandler &prm);

    /// @p output_directory is the run's (a reference is written there);
    /// @p base_level: see MeshRefinement::parse_parameters().
    void
    parse_parameters(ParameterHandler         &prm,
                     const std::string        &output_directory,
                     const TimeDiscretization &time,
                     const unsigned int        base_level);

    const MeshRefinement<dim> &
    refinement() const;

    unsigned int
    n_cycles() const;
    /// The section "Reference solution".
    const ReferenceSolution &
    reference() const
    {
      return reference_solution;
    }

    /// Before the first cycle: read the reference's index, if compared
    /// (collective).
    void
    prepare(const MPI_Comm communicator);

    /**
     * A cycle on @p triangulation begins: no errors yet, indicators zero.
     * Returns how often the time step is halved on this mesh (k refined
     * with h, see MeshRefinement).
     */
    unsigned int
    start_cycle(const unsigned int                      cycle,
                const parallel::TriangulationBase<dim> &triangulation);

    /// Before the cycle's first step, on its time grid @p time: throw a
    /// message naming the entries if the reference shares fewer than two
    /// times t > 0 with it (ReferenceSolution::check_common_times()).
    void
    check_reference_times(const TimeDiscretization &time) const;

    /// The next cycle's mesh from the cell @p indicators of this one.
    void
    refine(parallel::TriangulationBase<dim>   &triangulation,
           const Vector<float>                &indicators,
           const std::set<types::boundary_id> &contact_boundary_ids);

    /**
     * After step @p n at @p time: write a snapshot for a later comparison
     * (in the last cycle, at the snapshot times) and compare with the
     * reference where it has this time, adding the errors to
     * @p statistics and @p line. @p snapshot makes this rank's snapshot.
     */
    void
    add_reference_statistics(const unsigned int                    n,
                             const TimeDiscretization             &time,
                             const std::function<Snapshot<dim>()> &snapshot,
                             Statistics                           &statistics,
                             std::string                          &line,
                             const MPI_Comm communicator);

    /// The time spent on snapshots and comparisons in this cycle, which is
    /// not the run's.
    double
    diagnostics_time() const;

    /// The cycle's row of the table, with the error estimate of
    /// @p estimator if it is active (also to convergence.csv in
    /// @p base_directory, by rank 0, with cycles or a reference).
    void
    finish_cycle(const parallel::TriangulationBase<dim> &triangulation,
                 const types::global_dof_index           n_dofs,
                 const TimeDiscretization               &time,
                 const ErrorEstimator<dim>              &estimator,
                 const double                            wall_time,
                 const std::string                      &base_directory,
                 const MPI_Comm                          communicator);

    /// The table for the screen, with run times unless @p deterministic;
    /// empty for a single run without reference.
    std::string
    table_text(const std::string &base_directory,
               const bool         deterministic) const;

  private:
    unsigned int
    halvings_from_estimate(const unsigned long long cells) const;

    MeshRefinement<dim> mesh_refinement;
    ReferenceSolution   reference_solution;
    ConvergenceTable    convergence_table;
    unsigned int        current_cycle = 0;
    /// The equivalent mesh size of the first cycle (for k proportional to h).
    double first_mesh_size = 0;
    /// How often the current cycle halves Time/Time step.
    unsigned int halvings = 0;
    /// The errors against the reference in the current cycle: the largest
    /// over the common times, their sum's largest, and those at T.
    ErrorNorms   max_error, final_error;
    double       max_error_sum  = 0;
    unsigned int compared_times = 0;
    double       diagnostics    = 0;
  };
} // namespace VPContact

#endif
