// Section "Checkpoint": when a run writes checkpoints, where, how it stops on
// a signal, and how a checkpoint is put in place and found again on resume.
#ifndef vpcontact_checkpointing_h
#define vpcontact_checkpointing_h

#include <vpcontact/app/folder_lock.h>
#include <vpcontact/app/stop_signal_catcher.h>
#include <vpcontact/checkpoint/checkpoint_metadata.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Section "Checkpoint". A checkpoint is the folder Checkpoint/Folder
   * (default: checkpoint inside Output/Directory) holding the mesh with the
   * fields (CheckpointFields), checkpoint.json (CheckpointMetadata) and the
   * manifest (CheckpointManifest); see doc/checkpoint.md.
   *
   * A new checkpoint is written into FOLDER.new; once its manifest is on
   * disk, the previous FOLDER.old is removed, FOLDER becomes FOLDER.old and
   * FOLDER.new becomes FOLDER. At every moment one of the three names holds
   * a complete checkpoint, and the previous complete one is kept as a
   * fallback for a damaged newest one.
   *
   * The parameters that define the problem (every entry except the sections
   * Output, Checkpoint and Solver and the entry Time/End time) are recorded
   * in the checkpoint, and a run resumes only with the same values.
   */
  class Checkpointing
  {
  public:
    /// What to do at the end of a step.
    struct Decision
    {
      bool write = false;
      /// Stop after writing: a signal arrived on some rank.
      bool stop = false;
      /// That signal (the largest number if ranks differ).
      int signal = 0;
    };

    static void
    declare_parameters(ParameterHandler &prm);

    /// Read the section and record the parameters that define the problem.
    /// @p directory is Output/Directory, which OutputWriter owns and
    /// parses: the default checkpoint folder lies in it.
    void
    parse_parameters(ParameterHandler &prm, const std::string &directory);

    /**
     * Record @p value under @p entry with the parameters that define the
     * problem, for an input that is not a parameter itself (the contents of
     * the mesh file): a resumed run with another value is refused.
     */
    void
    record_problem_input(const std::string &entry, const std::string &value);

    /// Whether this run continues from a checkpoint.
    bool
    resume() const;

    /// Whether checkpoints are written every M steps or S seconds.
    bool
    writes_periodically() const;

    /// Whether signals stop the run with a checkpoint.
    bool
    stops_on_signal() const;

    /// Record that a signal stopped the run after its checkpoint.
    void
    note_stopped_on_signal()
    {
      stopped_on_signal = true;
    }

    /// Whether a signal stopped the run after its checkpoint.
    bool
    stopped() const
    {
      return stopped_on_signal;
    }

    /// The folder of the current checkpoint.
    const std::string &
    folder() const;

    /// The parameters that define the problem, "Section/Entry" -> value.
    const std::map<std::string, std::string> &
    problem_parameters() const;

    /**
     * Collective, once at the end of every step @p n of @p n_steps: write
     * every Checkpoint/Every steps steps and when Checkpoint/Every seconds
     * have passed since the last checkpoint (or the start; measured on rank
     * 0), and write and stop when a signal arrived on any rank (unless the
     * run is complete anyway). All ranks get the same answer.
     */
    Decision
    decide(const unsigned int n,
           const unsigned int n_steps,
           const MPI_Comm     communicator);

    /**
     * Collective, before the run computes: throw a message naming
     * Checkpoint/Folder if checkpoints may be written (periodically or on a
     * signal) and FOLDER, FOLDER.new or FOLDER.old exists without being a
     * checkpoint folder of this program (see write_folder_marker()), if
     * FOLDER holds the working directory or Output/Directory (which the
     * rotation would rename), or if its parent folder cannot be written.
     * Then claims FOLDER for this run by the lock file FOLDER.lock beside
     * it (throws naming the other run if one holds it).
     */
    void
    check_folders(const std::string &output_directory,
                  const MPI_Comm     communicator);

    /**
     * Collective: make FOLDER.new empty, mark it as this program's and
     * return its name; the fields are then saved into it. Throws, leaving
     * the previous checkpoint as it is, if the disk has not room for
     * @p n_bytes with a margin.
     */
    std::string
    start_writing(const double n_bytes, const MPI_Comm communicator) const;

    /**
     * Collective: rank 0 writes @p metadata and the manifest into
     * FOLDER.new, checking the files against @p expected_sizes (file name
     * -> bytes meant to be written), and rotates the folders as described
     * above; every rank throws if that failed. Restarts the clock of Every
     * seconds.
     */
    void
    finish_writing(const CheckpointMetadata                    &metadata,
                   const std::map<std::string, std::uintmax_t> &expected_sizes,
                   const MPI_Comm                               communicator);

    /**
     * Collective: the newest complete checkpoint among FOLDER, FOLDER.new
     * and FOLDER.old, checked against its manifest before anything reads it.
     * Says on @p out when it uses another than FOLDER and why. Throws a
     * message naming the folder and the damaged file if there is none.
     */
    CheckpointMetadata
    find_checkpoint(const MPI_Comm communicator, ConditionalOStream &out) const;

    /**
     * Throw a message listing the entries that differ if @p metadata was
     * written by a run of another problem.
     */
    void
    check_compatibility(const CheckpointMetadata &metadata) const;

  private:
    /**
     * Why FOLDER, FOLDER.new or FOLDER.old may not be touched, or "": one
     * of them is not a checkpoint folder of this program, or holds a file
     * that no checkpoint wrote.
     */
    std::string
    ownership_problem() const;

    /**
     * "Checkpoint/Folder = FOLDER: ", or, where the user left it empty,
     * "Output/Directory = DIR (its checkpoints go to DIR/checkpoint): ": the
     * start of a message about the checkpoint folder, naming the entry the
     * user set.
     */
    std::string
    folder_entry() const;

    unsigned int every_steps       = 0;
    double       every_seconds     = 0;
    bool         resume_run        = false;
    bool         catch_signals     = true;
    bool         stopped_on_signal = false;
    std::string  checkpoint_folder;
    /// Whether Checkpoint/Folder was set (else it derives from the next).
    bool        folder_set_by_user = false;
    std::string output_directory;

    std::map<std::string, std::string> parameters;
    /// The lock of FOLDER.lock on rank 0, held to the end of the run: two
    /// runs with one checkpoint folder would rotate each other's files.
    std::unique_ptr<FolderLock>           folder_lock;
    std::chrono::steady_clock::time_point last_checkpoint
      = std::chrono::steady_clock::now();
  };
} // namespace VPContact

#endif
