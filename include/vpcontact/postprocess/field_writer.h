// Writing the .vtu piece of one field output, in a thread of its own while the
// time steps go on, or at once.
#ifndef vpcontact_field_writer_h
#define vpcontact_field_writer_h

#include <vpcontact/postprocess/vtu_piece.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/numerics/data_component_interpretation.h>

#include <cstdint>
#include <future>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /// Which fields form vectors: (first, last, name, interpretation), as
  /// deal.II's DataOutInterface::get_nonscalar_data_ranges() gives them.
  using VectorRanges = std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>;

  /**
   * The .vtu piece of one field output and the names of its fields, as the
   * .pvtu record lists them: what a piece file is made of, without
   * references to the vectors it was taken from, so that it can be written
   * while those vectors change.
   */
  struct FieldPiece
  {
    VtuPiece piece;
    /// The names of the point fields, one per component (a vector's name
    /// repeated), and which of them form vectors, as deal.II's DataOut
    /// names them.
    std::vector<std::string> names;
    VectorRanges             vector_ranges;
    /// The names of the cell fields.
    std::vector<std::string> cell_names;
  };

  /**
   * Compresses and writes the .vtu piece of one field output. In a thread
   * of its own, this overlaps with the next steps, as ASPECT's "Write in
   * background thread" does. Not a task of deal.II's threads (TBB): a
   * thread that waits for the end of a parallel loop runs other tasks of
   * its arena meanwhile, so the loops of the next steps (right-hand side,
   * stress update) could take up the whole write and wait for it. The
   * thread runs at the lowest scheduling priority, so that it takes only
   * the cores the steps leave idle. The piece is written through a
   * temporary file and a rename, so that it is on disk either whole or not
   * at all.
   *
   * One write at a time: start() waits for the previous one. A failure in
   * the background is reported by wait(), not thrown there, so that the
   * caller can tell every MPI rank.
   *
   * The points and cells of a piece are the same at every output until
   * the mesh changes. Where it writes at once, holding up the steps, the
   * writer keeps them compressed and encoded (VtuPiece::mesh_sections())
   * with their fingerprint, and a piece of the same fingerprint is written
   * with them, its own points and cells freed at start(). In the
   * background it compresses every piece whole and keeps nothing.
   */
  class FieldWriter
  {
  public:
    /// Waits for a write still under way (its failure is dropped).
    ~FieldWriter();

    /**
     * Write @p fields to the file @p filename: in a thread
     * (std::async) if @p in_background, else before returning (a failure is
     * still reported by wait()).
     */
    void
    start(FieldPiece       &&fields,
          const std::string &filename,
          const bool         in_background);

    /// Whether a write was started and not yet waited for.
    bool
    pending() const;

    /**
     * Wait for the write started last and return what went wrong, the
     * message naming the file, or an empty string if the piece is on disk.
     */
    std::string
    wait();

  private:
    std::future<std::string> write;
    /// The mesh sections of the last piece written at once, and their
    /// fingerprint.
    std::shared_ptr<const std::string> mesh_sections;
    std::uint64_t                      mesh_fingerprint = 0;
    /// Whether a write was started and not yet waited for, and what went
    /// wrong with a write done at once.
    bool        started = false;
    std::string failure;
  };
} // namespace VPContact

#endif
