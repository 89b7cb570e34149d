// Copies an owned Trilinos vector into a ghosted one (its owned and ghost
// entries) with one Epetra_Import kept for as long as the layouts stay.
#ifndef vpcontact_ghost_exchange_h
#define vpcontact_ghost_exchange_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_Import.h>
#include <Epetra_Map.h>
#include <Epetra_Vector.h>
#include <memory>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * to = from for two vectors with the same owned entries (their ghost
   * entries, if any, are neither read nor written): the owned values are
   * copied.
   *
   * Why not deal.II's assignment: in deal.II 9.4 it builds an
   * Epetra_Import on every call between two vectors initialized each from
   * the same index set (seen in a profile: a hash lookup per index and a
   * permuted copy), even on one rank.
   */
  void
  copy_owned_values(const LA::MPI::Vector &from, LA::MPI::Vector &to);

  /**
   * The owned entries of @p full, a vector on all degrees of freedom
   * numbered by blocks, into the blocks of @p blocks, which split the same
   * owned entries: on each rank the owned entries of block b follow those
   * of the blocks before it in the local entries of @p full.
   */
  void
  copy_into_blocks(const LA::MPI::Vector &full, LA::MPI::BlockVector &blocks);



  /**
   * ghosted = owned, for vectors of the same global size, the first with
   * ghost entries.
   *
   * Why not deal.II's assignment: in deal.II 9.4 it builds a new
   * Epetra_Import on every call, even on one rank (where the ghosted layout
   * lists the same indices as the owned one but is not recognized as the
   * same), and building it walks every index of both layouts with a hash
   * lookup each. The simulator copies the displacement and the damage into
   * their ghosted vectors several times per step. Here the import is built
   * once and reused while both vectors keep their layouts (checked on every
   * call by the address of the layout data, which a vector keeps until it
   * is reinitialized; a new address costs one full comparison); where the two
   * layouts are the same, the values are copied directly.
   *
   * One exchange may serve several pairs of vectors in turn (the damage
   * step copies zeta_{n-1} and then each new zeta into the same ghosted
   * vector, from two owned vectors with layouts of their own): it keeps
   * the last few pairs of layouts it has seen. With only the last pair
   * kept, every alternation cost a full comparison and a new import
   * (in a profile of the paper scene at 512^2 cells, the comparison alone
   * took 1.2 % of the samples, in the damage step).
   */
  class GhostExchange
  {
  public:
    void
    copy(const LA::MPI::Vector &owned, LA::MPI::Vector &ghosted);

    /**
     * ghosted = owned for a vector of blocks and a ghosted vector on all
     * of their degrees of freedom, numbered by blocks (block b's indices
     * follow those of the blocks before it): each block goes straight into
     * its part of the ghosted vector's entries, which deal.II keeps sorted
     * by index, without a vector on all degrees of freedom in between.
     */
    void
    copy(const LA::MPI::BlockVector &owned, LA::MPI::Vector &ghosted);

  private:
    /// One pair of layouts seen: copies of the two layouts (they keep the
    /// layout data alive, so that the same data pointer means the same
    /// layout), whether they are the same, and the import between them if
    /// not.
    struct LayoutPair
    {
      std::unique_ptr<Epetra_BlockMap> source_layout;
      std::unique_ptr<Epetra_BlockMap> target_layout;
      bool                             same_layouts = false;
      std::unique_ptr<Epetra_Import>   importer;
    };

    /// The pair for these layouts: a kept one, or a new one that replaces
    /// the least recently used when max_pairs are kept.
    LayoutPair &
    pair_for(const Epetra_BlockMap &source, const Epetra_BlockMap &target);

    /// The ghosted vector's part for each block of a block vector: its
    /// first local entry, and its entries as a layout in the block's own
    /// indices (the index less the block's first), for as long as the
    /// ghosted vector keeps its layout.
    struct BlockParts
    {
      std::unique_ptr<Epetra_BlockMap>              ghosted_layout;
      std::vector<std::size_t>                      first_entry;
      std::vector<std::unique_ptr<Epetra_BlockMap>> layouts;
    };

    /// The parts for this ghosted vector's layout: kept ones, or new ones
    /// that replace the least recently used when max_block_parts are kept
    /// (each holds its layouts, and with them the old mesh's until it is
    /// replaced). The
    /// displacement copies its increment and its solution, two ghosted
    /// vectors of layouts of their own, in turn within every step; with
    /// only the last parts kept, each alternation walked every index and
    /// built new layouts, and with them new imports.
    const BlockParts &
    block_parts_for(const LA::MPI::BlockVector &owned,
                    const LA::MPI::Vector      &ghosted);

    static std::unique_ptr<BlockParts>
    make_block_parts(const LA::MPI::BlockVector &owned,
                     const LA::MPI::Vector      &ghosted);

    /// The pairs and the block parts, the most recently used first.
    std::vector<std::unique_ptr<LayoutPair>> pairs;
    std::vector<std::unique_ptr<BlockParts>> block_parts;
    static constexpr unsigned int            max_pairs       = 4;
    static constexpr unsigned int            max_block_parts = 2;
  };
} // namespace VPContact

#endif
