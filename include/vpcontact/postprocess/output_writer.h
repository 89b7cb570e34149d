// Everything the run writes to disk: the .pvtu/.vtu fields every M steps, the
// .pvd time series and statistics.csv, in one output folder.
#ifndef vpcontact_output_writer_h
#define vpcontact_output_writer_h

#include <vpcontact/app/folder_lock.h>
#include <vpcontact/postprocess/field_writer.h>
#include <vpcontact/postprocess/statistics.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/numerics/data_component_interpretation.h>

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Output".
   *
   * Files that describe the run as a whole (the .pvd record and
   * statistics.csv) are rewritten after every step through a temporary file
   * and a rename, so that a run that stops (an error, a kill) leaves them
   * complete up to the last finished step, never half-written.
   *
   * The .vtu pieces of a field output are compressed and written by a
   * FieldWriter, by default in a task of its own while the next steps are
   * computed. The .pvtu and .pvd records name a field output only once
   * every rank's piece is on disk: when the next field output starts, and
   * in finish_field_output().
   */
  template <int dim>
  class OutputWriter
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Create the output folder, claim it for this run (a FolderLock held
     * until this object is destroyed) and check that it can be written, on
     * rank 0, and tell every rank. Throws with a message naming
     * Output/Directory, also when another run holds the folder.
     */
    void
    prepare_directory(const MPI_Comm communicator);

    /**
     * Throw, naming Output/Directory and the first rank that does not see
     * the folder rank 0 prepared, if fields are written and a rank cannot
     * see it (collective).
     */
    void
    check_seen_by_all_ranks(const MPI_Comm communicator) const;

    /**
     * The files and folders in Output/Directory that this run would
     * replace although vpcontact did not write them: those with the names
     * of its outputs, in a folder without the output marker. Serial.
     */
    std::vector<std::string>
    foreign_outputs() const;

    /// Whether step @p n of @p n_steps writes fields.
    bool
    writes_fields_at(const unsigned int n, const unsigned int n_steps) const;

    /**
     * Write @p fields for step @p n: this rank's .vtu piece, in the
     * background if so chosen and @p steps_follow (no step would overlap
     * the write of the run's last output, which the run then waits for:
     * written at once, it has all of the rank's threads). The field output
     * before it is finished first.
     */
    void
    write_fields(FieldPiece       &&fields,
                 const unsigned int n,
                 const double       time,
                 const bool         steps_follow,
                 const MPI_Comm     communicator);

    /**
     * Wait for the pieces of the last field output on every rank, then
     * write its .pvtu record and the .pvd record (rank 0). Collective;
     * throws on every rank if a piece could not be written on any. Called
     * at the end of a run and before a checkpoint.
     */
    void
    finish_field_output(const MPI_Comm communicator);

    /**
     * The same after an error stopped the run, without talking to the
     * other ranks (they may not be here): wait for this rank's piece and,
     * on rank 0, if it is on disk, add the output to the records. Never
     * throws.
     */
    void
    finish_field_output_after_error() noexcept;

    /// Rewrite statistics.csv (rank 0 writes).
    void
    write_statistics(const Statistics &statistics,
                     const MPI_Comm    communicator) const;

    /// Screen output that depends only on the discrete solution.
    bool
    deterministic_screen_output() const;

    /// Whether to time one displacement solve at the end (benchmarks).
    bool
    report_solve_floor() const;

    /// The folder written to now (the cycle's folder during cycles).
    const std::string &
    directory() const;
    /// Output/Directory itself (where the convergence table goes).
    const std::string &
    base_directory() const;
    /**
     * Write the next fields, statistics.csv and .pvd into the folder
     * @p subfolder of Output/Directory (a new time series), or into
     * Output/Directory itself if @p subfolder is empty.
     */
    void
    set_subfolder(const std::string &subfolder);

    /// (time, .pvtu file) of every field output so far (for checkpoints).
    const std::vector<std::pair<double, std::string>> &
    field_outputs() const;

    /**
     * A resumed run: take the field outputs of the checkpoint and rewrite
     * the .pvd record with them (rank 0), dropping any step written after
     * the checkpoint by the run that stopped. @p folder is where the
     * checkpointed run wrote them (CheckpointMetadata::output_directory):
     * if that is another folder, the .pvtu records and .vtu pieces are
     * brought into this one (hard links, else copies), so that the record
     * lists files of this folder; an output whose files are missing is left
     * out of the record. Returns a note for the screen saying what was
     * brought or left out, or "".
     */
    std::string
    restore_field_outputs(
      const std::vector<std::pair<double, std::string>> &outputs,
      const std::string                                 &folder,
      const MPI_Comm                                     communicator);

  private:
    /// Rewrite solution.pvd from times_and_names (rank 0 writes).
    void
    write_pvd_record(const MPI_Comm communicator) const;

    /// A field output whose pieces are being written: what its .pvtu and
    /// .pvd records need.
    struct PendingOutput
    {
      unsigned int             rank;
      double                   time;
      std::string              pvtu;
      std::vector<std::string> pieces;
      std::vector<std::string> names;
      VectorRanges             vector_ranges;
      std::vector<std::string> cell_names;
    };

    /// Write the .pvtu record of @p output (rank 0 calls this).
    void
    write_pvtu_record(const PendingOutput &output) const;

    std::string  output_directory    = "results";
    std::string  base_directory_name = "results";
    unsigned int output_every        = 10;
    bool         deterministic       = false;
    bool         solve_floor         = false;
    bool         in_background       = true;

    /// The flags of the .pvtu records.
    DataOutBase::VtkFlags vtk_flags;

    /// The claim on the output folder (rank 0), from prepare_directory().
    std::unique_ptr<FolderLock> lock;

    FieldWriter                  field_writer;
    std::optional<PendingOutput> pending_output;

    /// (time, .pvtu file) of every field output so far, for the .pvd record.
    std::vector<std::pair<double, std::string>> times_and_names;
  };

  /**
   * Write @p content to @p filename through a temporary file in the same
   * folder and a rename, so that readers see either the old or the new
   * file. Throws with the file's name if it cannot be written.
   */
  void
  write_file_atomically(const std::string &filename,
                        const std::string &content);

  /**
   * The same with the content written into the file's stream by @p write:
   * for a large file, which then need not be held in memory as one string
   * besides what it is made from. If @p write throws, the temporary file is
   * removed and the exception passed on.
   */
  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &write);

  /**
   * Folders this program makes carry a marker file (@p marker, e.g.
   * ".vpcontact-output"), so that it can tell them from a user's: it
   * replaces or removes files only in folders that carry the marker.
   * Writes the marker into @p folder; throws if it cannot.
   */
  void
  write_folder_marker(const std::string &folder, const std::string &marker);

  /// Whether @p folder carries @p marker (see write_folder_marker()).
  bool
  has_folder_marker(const std::string &folder, const std::string &marker);

  /// The marker of an output folder.
  inline const std::string output_folder_marker = ".vpcontact-output";

  /// The lock file of an output folder (see FolderLock).
  inline const std::string output_folder_lock = ".vpcontact-lock";

  /**
   * Throw a message naming @p entry if the files this program writes below
   * @p folder would have paths longer than the system takes (PATH_MAX).
   */
  void
  check_path_length(const std::string &entry, const std::string &folder);

  /**
   * Run @p task on rank 0 of @p communicator only and return, on every
   * rank, the message of what it threw (empty if it did not), so that all
   * ranks can stop together.
   */
  std::string
  problem_on_rank_zero(const MPI_Comm               communicator,
                       const std::function<void()> &task);

  /**
   * Call @p write on rank 0 of @p communicator only; if it throws, every
   * rank throws its message, so that a failed write stops the whole run
   * instead of leaving the other ranks waiting for rank 0.
   */
  void
  write_on_rank_zero(const MPI_Comm               communicator,
                     const std::function<void()> &write);
} // namespace VPContact

#endif
