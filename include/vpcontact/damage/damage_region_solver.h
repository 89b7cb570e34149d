// CG for the damage problem on the free nodes only, preconditioned by an
// incomplete Cholesky factorization of the matrix restricted to a region
// around them (or its diagonal variant, applied with Eisenstat's trick):
// the work of an iteration follows the free set, not the mesh.
#ifndef vpcontact_damage_region_solver_h
#define vpcontact_damage_region_solver_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/owned_rows.h>

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * While the damage is young, most nodes sit at the upper bound zeta = 1
   * and are held in every solve of the damage problem (at 512^2 cells in
   * the paper scene, the free nodes are 1-12 % of all up to t = 0.5). A CG
   * on the whole vector that masks the held entries, with a preconditioner
   * of the whole matrix, pays for every node in every iteration. This
   * class runs the preconditioned CG over the free nodes alone:
   *
   * - the matrix-vector product visits the rows of the free nodes (the
   *   search directions vanish elsewhere, so the columns of held nodes add
   *   nothing);
   * - the preconditioner is MIC(0) or IC(0) of K_RR (or the diagonal
   *   variant below), K_RR being the matrix restricted to a
   *   region R of this rank's nodes that holds the free nodes and a margin
   *   of rings of neighbours around them, applied to vectors that vanish
   *   on R minus the free nodes, with the result masked alike. That is a
   *   principal submatrix of an SPD matrix, so the CG stays a CG. Between
   *   ranks it is block Jacobi, as Ifpack's IC is;
   * - the vector operations run over the free nodes.
   *
   * The region is built at the first solve of a step (begin_step()) from
   * the free set of that solve, and again within the step whenever a free
   * node falls outside it: it depends only on the step's sets, so a run
   * resumed from a checkpoint computes the same bits. Built over all nodes
   * it is the (M)IC(0) of this rank's block of K.
   *
   * The third preconditioner, Preconditioner::diagonal (see
   * solve_eisenstat()), is P = (D + L) D^{-1} (D + L^T) with L the
   * strictly lower part of K_RR itself and D a diagonal that keeps the row
   * sums. Since its triangular factors hold K's own entries, Eisenstat's
   * trick runs CG on (D + L)^{-1} K (D + L^T)^{-1} at the cost of the two
   * sweeps alone: no separate matrix-vector product and no factor besides
   * K, about a third less memory traffic per iteration than (M)IC(0),
   * for a few more iterations.
   *
   * The vectors are Trilinos vectors of the owned compact damage entries
   * (see DamageSystem); positions below are positions in their local
   * storage.
   */
  class DamageRegionSolver
  {
  public:
    /// The preconditioner on the region (see the class documentation).
    enum class Preconditioner
    {
      /// IC(0) of K_RR.
      incomplete_cholesky,
      /// MIC(0) of K_RR (see factorize_by_columns()).
      modified_incomplete_cholesky,
      /// (D + L) D^{-1} (D + L^T), D keeping the row sums, with
      /// Eisenstat's trick (see solve_eisenstat()).
      diagonal
    };

    /**
     * Solve with the matrix of @p rows (kept by reference: they must
     * outlive this object's use), whose columns are positions in a ghosted
     * vector over them (and, for the region, owned positions). Once per
     * mesh and step size.
     */
    void
    initialize(const OwnedRows &rows, const Preconditioner kind);

    /// Forget the region: the next solve builds it from its free set.
    void
    begin_step();

    /**
     * Solve K_FF x_F = b_F for the free nodes F (the owned positions not in
     * @p held), with x = 0 on the held ones; @p b and @p x (the start
     * vector) must vanish on them. Stops at a residual of @p tolerance
     * times |b| (x = 0 without iterations if b = 0). Returns the number of
     * iterations, or throws
     * SolverControl::NoConvergence after @p max_iterations.
     */
    unsigned int
    solve(const LA::MPI::Vector           &b,
          LA::MPI::Vector                 &x,
          const std::vector<unsigned int> &held,
          const double                     tolerance,
          const unsigned int               max_iterations);

    /**
     * solve() with the free nodes given: @p free, the ascending owned
     * positions of F. @p b and @p x (the start vector) are read on F
     * alone and x is written there alone.
     */
    unsigned int
    solve_free(const LA::MPI::Vector           &b,
               LA::MPI::Vector                 &x,
               const std::vector<unsigned int> &free,
               const double                     tolerance,
               const unsigned int               max_iterations);

    /// How often the region was built on this rank (for the tests).
    unsigned int
    n_region_builds() const;

    /// The absolute residual the last solve aimed at: the tolerance times
    /// |b| on its free nodes (for the message of a solve that misses it).
    double
    target_of_last_solve() const;

  private:
    /// solve_free() on the local storage of the vectors (owned positions).
    unsigned int
    solve_free(const double                    *b,
               double                          *x,
               const std::vector<unsigned int> &free,
               const double                     tolerance,
               const unsigned int               max_iterations);

    /// The free set @p free (ascending owned positions); builds the region
    /// if it does not hold them.
    void
    take_free_nodes(const std::vector<unsigned int> &free);

    /// R = F and @p rings rings of neighbours around it; (M)IC(0) of K_RR.
    void
    build_region(const unsigned int rings);

    /// Renumber R level by level, for the triangular sweeps.
    void
    order_by_levels();


    /// The strictly lower triangle of K_RR by rows (region indices,
    /// sorted) and its diagonal.
    void
    collect_lower_triangle();

    /// L^T by rows (upper_start, upper_column); returns the position in
    /// factor_value of each of its entries.
    std::vector<unsigned int>
    transpose_lower_triangle();

    /// The lower triangle of K_RR, factorized; L^T for the backward sweep.
    void
    factorize_region();

    /// (M)IC(0) in place, column by column; @p entry_in_rows: the position
    /// in factor_value of each entry of L^T.
    void
    factorize_by_columns(const std::vector<unsigned int> &entry_in_rows);

    /// D of Preconditioner::diagonal on K_RR, and the entries of the region
    /// rows in ghost columns (for the coupling between ranks).
    void
    prepare_diagonal_preconditioner();

    /// solve() with Preconditioner::diagonal, on the free set selected.
    unsigned int
    solve_eisenstat(const double      *b,
                    double            *x,
                    const double       tolerance,
                    const unsigned int max_iterations);

    /// The share of each region row's entries in other ranks' columns that
    /// D of Preconditioner::diagonal and the pivots of MIC(0) take in (none
    /// on one rank).
    std::vector<double>
    cut_share_of_row_sums() const;

    /// The entries of the region's rows in other ranks' columns, and the
    /// owned entries the import sends (see prepare_diagonal_preconditioner()).
    void
    collect_cut_coupling();

    /// r = b - K x on F in region indices, for solve_eisenstat(); returns
    /// |b|^2 over F, summed over the ranks.
    double
    eisenstat_start(const double *b, double *x);

    /// One update of solve_eisenstat()'s vectors with step @p alpha, and
    /// the sums r^ D r^ and r . r over the ranks.
    std::pair<double, double>
    eisenstat_update(const double alpha);

    /// x += C^{-T} x^ at the end of solve_eisenstat().
    void
    eisenstat_finish(double *x);

    /// The diagonals of the sweeps for the current free set (zero off it).
    void
    mask_diagonal();

    /// y = (D + L)^{-1} (src + shift) on R (forward sweep), and w = the
    /// product of (D + L) with t + y (see solve_eisenstat()); returns the
    /// local part of src . (t + y). With @p t null only y.
    double
    forward_sweep(const double *src, const double *t, double *y, double *w);

    /// t = (D + L^T)^{-1} (D_F rh + beta src) on R, where src is updated
    /// to that argument first (backward sweep, see solve_eisenstat()).
    void
    backward_sweep(const double *rh, double *src, const double beta, double *t);

    /// off = K_off t, the coupling to other ranks' free nodes.
    void
    add_off_rank_coupling(const std::vector<double> &t);

    /// Sum over the ranks of two numbers at once.
    std::pair<double, double>
    global_sums(const double a, const double b) const;

    /// dst = K src on the free rows (src vanishes off F); returns the local
    /// part of p . dst over F for @p p in the owned layout (see solve()).
    double
    vmult_free(std::vector<double> &dst, const double *src, const double *p);

    /// dst = IC(K_RR)^{-1} src on F (src vanishes off F; dst is set on F);
    /// returns the local part of src . dst over F.
    double
    precondition_free(std::vector<double> &dst, const std::vector<double> &src);

    double
    dot_free(const std::vector<double> &a, const std::vector<double> &b) const;

    /// product = K x on F for the start vector @p x (zero off F), through
    /// direction; returns |b|^2 over F, summed over the ranks. The start
    /// of both CG loops (solve() and solve_eisenstat()).
    double
    start_product(const double *b, const double *x);

    /// product = K direction on F; returns direction . product over F, on
    /// every rank.
    double
    multiply_direction();

    /// The owned position of the column at ghosted position @p c, or -1
    /// for a ghost (whose entry is at c - n_owned among the halo's).
    int
    owned_of_ghosted(const unsigned int c) const
    {
      return c < n_owned ? static_cast<int>(c) : -1;
    }

    /// Sum over the ranks (none on one).
    double
    global_sum(const double local) const;

    /// Zero the work vectors on the free set of the solve just done.
    void
    clean_up();

    MPI_Comm communicator  = MPI_COMM_SELF;
    bool     serial_layout = true;

    // K's owned rows: CSR, columns as positions in the ghosted layout of
    // the halo (the owned positions, then the ghost entries).
    const OwnedRows *rows    = nullptr;
    unsigned int     n_owned = 0;
    Preconditioner   kind    = Preconditioner::modified_incomplete_cholesky;

    // The free set of the current solve.
    std::vector<bool>         is_free;
    std::vector<unsigned int> free_nodes;

    // The region R (owned positions, level by level; see
    // order_by_levels()), each owned position's index in it (or -1), and
    // the (M)IC(0) factor L of K_RR (L L^T ~ K_RR): the strictly lower part in
    // CSR over region indices, the same transposed (the strictly upper
    // part of L^T), and the diagonal.
    std::vector<unsigned int> region;
    std::vector<int>          region_index;
    std::vector<unsigned int> factor_start;
    std::vector<unsigned int> factor_column;
    std::vector<double>       factor_value;
    std::vector<unsigned int> upper_start;
    std::vector<unsigned int> upper_column;
    std::vector<double>       upper_value;
    std::vector<double>       factor_diagonal;
    std::vector<double>       inverse_diagonal;
    bool                      region_valid = false;
    unsigned int              builds       = 0;

    // Preconditioner::diagonal: D and 1/D on R, the diagonal of K_RR, and
    // per solve D, 1/D and K_kk - 2 D on F (zero on R \ F); the entries of
    // the region rows along the cut in ghost columns; the vectors of the
    // transformed CG (region indices).
    std::vector<double>       sweep_diagonal;
    std::vector<double>       sweep_inverse;
    std::vector<double>       diagonal_of_k;
    std::vector<double>       masked_diagonal;
    std::vector<double>       masked_inverse;
    std::vector<double>       masked_shift;
    std::vector<unsigned int> coupled_rows;
    std::vector<unsigned int> ghost_start;
    /// Positions in ghost_values (the halo's ghost entries).
    std::vector<unsigned int> ghost_column;
    std::vector<double>       ghost_value;

    /// See target_of_last_solve().
    double last_target = 0.;
    /// The owned positions the halo sends to other ranks, with their
    /// region index (or -1).
    std::vector<std::pair<unsigned int, int>> exported;
    std::vector<double>                       off_rank;
    std::vector<double>                       hat_residual;
    std::vector<double>                       hat_direction;
    std::vector<double>                       hat_update;
    std::vector<double>                       sweep_t;
    std::vector<double>                       sweep_s;
    std::vector<double>                       residual_change;
    std::vector<double>                       true_residual;

    // Work vectors (owned positions; zero off F between solves) and the
    // search direction in the ghosted layout (its ghost entries after the
    // owned ones), which the products read.
    std::vector<double> residual;
    std::vector<double> preconditioned;
    std::vector<double> product;
    std::vector<double> region_work;
    std::vector<double> direction;

    /// The exchange of the search direction and of the sweeps' vector t
    /// along the cut: deal.II's partitioner packs only the entries other
    /// ranks read (an Epetra_Import also copies every owned entry into the
    /// ghosted vector, a pass over the whole rank per iteration however
    /// small the free set).
    std::shared_ptr<const Utilities::MPI::Partitioner> halo;
    std::vector<double>                                halo_owned;
    std::vector<double>                                halo_send;
    std::vector<double>                                ghost_values;
    std::vector<MPI_Request>                           halo_requests;
  };
} // namespace VPContact

#endif
