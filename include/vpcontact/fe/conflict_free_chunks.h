// ConflictFreeChunks: the locally owned cells in chunks, and the chunks in
// colors whose chunks add to no common vector entry, so that the threads
// can add cell vectors by position without a serial copier.
#ifndef vpcontact_conflict_free_chunks_h
#define vpcontact_conflict_free_chunks_h

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <functional>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * A plan for adding cell vectors into the owned entries of a vector from
   * several threads at once. The cells (given by their number in a list of
   * the locally owned cells) are cut into consecutive chunks; a cell is
   * "plain" when none of its entries is constrained and all are owned, and
   * then its vector goes to the owned entries by position. The chunks are
   * colored greedily so that no two chunks of one color share an entry of
   * a plain cell: the chunks of one color may run in any threads at once,
   * and every entry receives its sums in the same order (color by color,
   * cell by cell) with any number of threads. The other cells go through
   * the constraints, one after the other, after the colors.
   *
   * The plan depends on the mesh and on which entries are constrained; it
   * is made again when the constrained entries change (outdated()).
   */
  class ConflictFreeChunks
  {
  public:
    /// The global indices of the entries of cell @p i, in the order of its
    /// cell vector.
    using CellIndices
      = std::function<void(const std::size_t i,
                           std::vector<types::global_dof_index> &)>;

    /**
     * Make the plan for @p n_cells cells, whose entries @p cell_indices
     * gives, with the owned entries [@p first_owned, @p first_owned +
     * @p n_owned) and @p constraints, in chunks of at most @p chunk_size
     * cells.
     */
    void
    reinit(const std::size_t                n_cells,
           const CellIndices               &cell_indices,
           const types::global_dof_index    first_owned,
           const types::global_dof_index    n_owned,
           const AffineConstraints<double> &constraints,
           const unsigned int               chunk_size);

    /**
     * Make the plan for cells whose entries are positions in one local
     * vector (owned and ghost entries alike): cell i adds to
     * @p cell_positions[i * n_entries + a], a < @p n_entries, and it is
     * plain where @p plain[i]; the other cells are left to the caller.
     * The plan keeps the positions (moved in), and positions() gives them
     * for every cell, the other cells' too. outdated() does not apply to
     * this plan: the caller makes it again with the mesh.
     */
    void
    reinit(std::vector<unsigned int> &&cell_positions,
           const unsigned int          n_entries,
           const std::vector<bool>    &plain,
           const unsigned int          chunk_size);
    /// The number of chunks.
    unsigned int
    n_chunks() const
    {
      return chunk_cells.size();
    }
    /// Forget the plan (the mesh has changed): outdated() is true.
    void
    clear()
    {
      made = false;
    }

    /// Whether the constrained entries, or the number of cells, differ
    /// from those of the last reinit(), or clear() was called since.
    bool
    outdated(const std::size_t                n_cells,
             const AffineConstraints<double> &constraints) const;

    /// The colors: each a list of chunk numbers.
    const std::vector<std::vector<unsigned int>> &
    colors() const
    {
      return color_chunks;
    }

    /// The plain cells of chunk @p c, in the order of the cells.
    const std::vector<std::size_t> &
    plain_cells(const unsigned int c) const
    {
      return chunk_cells[c];
    }

    /// The positions among the owned entries of the entries of plain cell
    /// @p i (as many as its cell vector has); for a plan made from
    /// positions, those given, for every cell.
    const unsigned int *
    positions(const std::size_t i) const
    {
      return &cell_positions[i * n_entries];
    }

    /// The cells that are not plain, in the order of the cells.
    const std::vector<std::size_t> &
    other_cells() const
    {
      return others;
    }

  private:
    /// The constrained entries, sorted, for outdated().
    static std::vector<types::global_dof_index>
    constrained_entries(const AffineConstraints<double> &constraints);

    /// The cells into chunks of @p chunk_size consecutive cells, the plain
    /// ones (@p plain) listed per chunk and the others apart, then colored.
    void
    make_chunks(const std::vector<bool> &plain, const unsigned int chunk_size);
    void
    color_chunks_greedily(const unsigned int n_chunks);

    bool                                   made = false;
    std::vector<types::global_dof_index>   constrained;
    std::size_t                            n_cells   = 0;
    unsigned int                           n_entries = 0;
    std::vector<std::vector<std::size_t>>  chunk_cells;
    std::vector<unsigned int>              cell_positions;
    std::vector<std::size_t>               others;
    std::vector<std::vector<unsigned int>> color_chunks;
  };
} // namespace VPContact

#endif
