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
    static constexpr unsigned int format_version = 2;

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
     * Flush every regular file of @p folder to disk, write the manifest of
     * them and flush it and the folder. Throws with the file's name if a
     * file cannot be read or written, or if a file named in
     * @p expected_sizes does not have the size recorded there (what was
     * meant to be written). Serial: call on one rank.
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
