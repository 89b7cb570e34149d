// Errors against a reference run: snapshots of the discrete solution written
// to disk cell by cell, and the norms of the paper's Theorem 2 between a run
// and a reference on a refinement of the same coarse mesh.
#ifndef vpcontact_reference_solution_h
#define vpcontact_reference_solution_h

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/grid/cell_id.h>

#include <functional>
#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The discrete state of a run at one time on a set of cells, in a form
   * that does not depend on the partition or the numbering of degrees of
   * freedom: for every cell its CellId (coarse cell and path of children),
   * its vertices, the displacement and damage at the vertices (Q1), and the
   * stress at the 2^dim Gauss points of the scheme's rule, in the order of
   * QGauss<dim>(2).
   *
   * Between two runs on refinements of the same coarse mesh, the CellIds
   * tell which cell of one contains a cell of the other, so that functions
   * of the coarser run can be evaluated exactly on the finer one.
   */
  template <int dim>
  class Snapshot
  {
  public:
    static constexpr unsigned int n_vertices
      = GeometryInfo<dim>::vertices_per_cell;
    static constexpr unsigned int n_stress
      = SymmetricTensor<2, dim>::n_independent_components;
    /// Numbers per cell: vertices, displacement, damage, stress.
    static constexpr unsigned int n_values
      = n_vertices * (2 * dim + 1 + n_stress);

    double time       = 0;
    bool   has_damage = false;

    /// Add a cell (@p damage is ignored without damage).
    void
    add_cell(const CellId                                 &id,
             const std::array<Point<dim>, n_vertices>     &vertices,
             const std::array<Tensor<1, dim>, n_vertices> &displacement,
             const std::array<double, n_vertices>         &damage,
             const std::array<SymmetricTensor<2, dim>, n_vertices> &stress);

    unsigned int
    n_cells() const;
    const CellId::binary_type &
    id(const unsigned int cell) const;
    Point<dim>
    vertex(const unsigned int cell, const unsigned int v) const;
    Tensor<1, dim>
    displacement(const unsigned int cell, const unsigned int v) const;
    double
    damage(const unsigned int cell, const unsigned int v) const;
    SymmetricTensor<2, dim>
    stress(const unsigned int cell, const unsigned int q) const;

    /// Append the cells of @p other (same time and fields).
    void
    append(const Snapshot<dim> &other);

    /// The snapshot as bytes (a versioned binary format) and back.
    std::vector<char>
    to_bytes() const;
    static Snapshot<dim>
    from_bytes(const std::vector<char> &bytes, const std::string &source);

  private:
    std::vector<CellId::binary_type> ids;
    std::vector<double>              values;
  };



  /// The three norms of Theorem 2 of a difference.
  struct ErrorNorms
  {
    /// ||eps(u - u_h)||_Q, the norm of V (equivalent to H1 by Korn).
    double displacement = 0;
    /// ||sigma - sigma_h||_Q (L2, with sigma:sigma).
    double stress = 0;
    /// ||zeta - zeta_h||_L2.
    double damage = 0;

    double
    sum() const
    {
      return displacement + stress + damage;
    }
  };

  /**
   * The errors of the run whose locally owned cells are @p run (on each
   * rank) against @p reference (all cells, on every rank), summed over the
   * ranks of @p communicator.
   *
   * Every reference cell must lie in a cell of the run (the reference is a
   * refinement of the run's mesh, at least as fine everywhere). On a
   * reference cell C inside a run cell A, the run's functions are evaluated
   * at the Gauss points of C mapped into A's unit cell: the displacement
   * and damage by A's Q1 shape functions, the stress by the Q1 function
   * through its values at A's Gauss points (the discontinuous Q1 field that
   * the values at the quadrature points define; for sigma_h = E eps(u_h) it
   * is exact). The integrands are then polynomials that the 2^dim-point
   * Gauss rule on C integrates exactly on parallelograms.
   *
   * Throws, with @p reference_name in the message, if the reference does not
   * cover the run's mesh or its cells are not where the run's are (a
   * different coarse mesh or geometry).
   */
  template <int dim>
  ErrorNorms
  compute_errors(const Snapshot<dim> &run,
                 const Snapshot<dim> &reference,
                 const std::string   &reference_name,
                 const MPI_Comm       communicator);



  /**
   * Section "Reference solution": writing this run's snapshots for later
   * comparisons, and comparing with the snapshots of another run.
   *
   * A reference is a folder with one file per snapshot time and an index,
   * reference.index, listing (time, file). Snapshots are gathered and
   * written by rank 0, so a reference can be read on any number of ranks.
   */
  class ReferenceSolution
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    /// @p output_directory is where "Write snapshots" writes (in a folder
    /// reference/ inside it).
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &output_directory);

    bool
    writes_snapshots() const;
    bool
    compares() const;
    /// Check that the snapshot interval is a multiple of the step @p k.
    void
    check_time_step(const double k, const double end_time) const;
    /// Whether step @p n (of step @p k) is a snapshot time.
    bool
    is_snapshot_step(const unsigned int n, const double k) const;

    /// Write @p local (this rank's cells) as the snapshot of its time.
    template <int dim>
    void
    write(const Snapshot<dim> &local, const MPI_Comm communicator);

    /// Read the reference index (once, before the first comparison), on
    /// rank 0 of @p communicator for all ranks (collective).
    void
    read_index(const MPI_Comm communicator);
    /// Whether the reference has a snapshot at time @p t.
    bool
    has_time(const double t) const;
    /**
     * Throw a message naming the entries unless the reference has snapshots
     * at two or more times t > 0 of a run of @p n_steps steps of @p k
     * (times @p time(n)): with fewer, the errors are those of t = 0 alone
     * (round-off) and the table's orders and effectivities mean nothing.
     * @p k_entry names the step ("Time/Time step = 0.1").
     */
    void
    check_common_times(const double                           k,
                       const unsigned int                     n_steps,
                       const std::function<double(unsigned)> &time,
                       const std::string                     &k_entry) const;
    /// The reference snapshot at time @p t (has_time(t) must hold), read
    /// on rank 0 of @p communicator for all ranks (collective).
    template <int dim>
    Snapshot<dim>
    read(const double t, const MPI_Comm communicator) const;
    /// The folder compared with, for messages.
    const std::string &
    comparison_folder() const;

  private:
    bool        write_snapshots = false;
    double      interval        = 0;
    std::string write_folder;
    std::string compare_folder;
    double      time_tolerance = 1e-9;
    /// (time, file name) of the reference compared with.
    std::vector<std::pair<double, std::string>> index;
    /// (time, file name) of the snapshots written so far.
    std::vector<std::pair<double, std::string>> written;
  };
} // namespace VPContact

#endif
