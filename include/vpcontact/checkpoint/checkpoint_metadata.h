// What a checkpoint records besides its fields (step, time, statistics, the
// parameters of the run), and the manifest that proves a checkpoint complete.
#ifndef vpcontact_checkpoint_metadata_h
#define vpcontact_checkpoint_metadata_h

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  /**
   * The part of a checkpoint that rank 0 writes as text, in the file
   * checkpoint.json of the checkpoint folder: where the run stands, what it
   * has written so far, and the parameters that define its problem.
   * Doubles are written with 17 significant digits, so that they read back
   * exactly.
   */
  struct CheckpointMetadata
  {
    /// The version of this layout; a checkpoint of another one is refused.
    /// Version 3: the mesh of a box is stored as the forest of its coarsest
    /// box (Geometry::base_level()).
    static constexpr unsigned int format_version = 3;

    /// The last completed time step and its time t_step.
    unsigned int step = 0;
    double       time = 0;
    /// The refinement cycle (0 while runs have a single mesh).
    unsigned int cycle = 0;
    /// The number of MPI ranks that wrote it (informative only).
    unsigned int n_ranks = 1;

    /// Sizes of the mesh and the discretisation, checked after loading.
    unsigned long long n_coarse_cells = 0;
    unsigned long long n_active_cells = 0;
    unsigned long long n_dofs         = 0;

    /// The text of statistics.csv up to this step.
    std::string statistics_csv;
    /// (time, .pvtu file) of every field output so far: the .pvd record.
    std::vector<std::pair<double, std::string>> field_outputs;
    /**
     * The folder those field outputs are in, an absolute path (empty in
     * checkpoints of versions before it was recorded): a run resumed into
     * another Output/Directory brings them from there.
     */
    std::string output_directory;
    /// Running extremes that the end-of-run summary reports, by name.
    std::map<std::string, double> counters;
    /**
     * "Section/Entry" -> value of every parameter that defines the mesh, the
     * discretisation or the physics (see Checkpointing).
     */
    std::map<std::string, std::string> parameters;

    /// The folder it was read from (not written).
    std::string folder;

    std::string
    to_json() const;

    /// Parse @p text; throws std::runtime_error saying what is wrong.
    static CheckpointMetadata
    from_json(const std::string &text);
  };

  /**
   * The manifest of a checkpoint folder, the file manifest.txt: the size and
   * CRC-32 of every other file in it. It is written last, after every file
   * has been flushed to disk, so a folder with a valid manifest is a
   * complete checkpoint, and a file that was truncated or changed since is
   * found by check_manifest() before p4est reads it (p4est aborts the run
   * on a damaged file rather than reporting it).
   */
  namespace CheckpointManifest
  {
    /// The name of the manifest inside a checkpoint folder.
    inline const std::string filename = "manifest.txt";

    /**
     * The marker of a checkpoint folder (see write_folder_marker()): the
     * program replaces and removes only folders that carry it.
     */
    inline const std::string marker = ".vpcontact-checkpoint";

    /**
     * Whether @p name is a file that a checkpoint of the simulator writes:
     * the mesh and its cell data (CheckpointFields::save() with the name
     * "mesh"), checkpoint.json, the manifest and the marker, the
     * temporary files they are written through, and the lock-test files
     * that MPI-IO writes beside them (is_lock_test_file()). A checkpoint
     * folder holds nothing else, except files that its manifest lists.
     */
    bool
    is_checkpoint_file(const std::string &name);

    /// Whether @p name is a file <file>.locktest.<rank> that Open MPI's
    /// MPI-IO writes beside @p file to test its locks, and leaves when the
    /// run is killed meanwhile.
    bool
    is_lock_test_file(const std::string &name, const std::string &file);

    /**
     * The entries of @p folder that a checkpoint did not write: neither
     * listed in its manifest nor checkpoint files (is_checkpoint_file()).
     * Those are the user's, and a folder holding one is neither removed
     * nor renamed. Serial.
     */
    std::vector<std::string>
    foreign_files(const std::string &folder);

    /**
     * Remove the files of the checkpoint in @p folder, those its manifest
     * lists and the checkpoint files, then the folder if that left it
     * empty. Never removes another file; throws, naming them, if any is
     * left. Serial.
     */
    void
    remove(const std::string &folder);

    /**
     * Flush the files of the checkpoint in @p folder to disk (the
     * checkpoint files and those named in @p expected_sizes), write the
     * manifest of them and flush it and the folder. Throws with the file's
     * name if a file cannot be read or written, if a file named in
     * @p expected_sizes does not have the size recorded there (what was
     * meant to be written), or if the folder holds a file the checkpoint
     * did not write. Serial: call on one rank.
     */
    void
    write(const std::string                           &folder,
          const std::map<std::string, std::uintmax_t> &expected_sizes = {});

    /**
     * An empty string if @p folder has a manifest and every file it lists
     * has the recorded size and checksum; otherwise what is wrong, in words
     * (e.g. "the file mesh_fixed.data has 120 bytes, the manifest records
     * 4200 (truncated)"). Serial.
     */
    std::string
    check(const std::string &folder);
  } // namespace CheckpointManifest
} // namespace VPContact

#endif
