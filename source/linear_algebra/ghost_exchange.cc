// GhostExchange: the import of owned entries into a ghosted vector, built
// once per pair of layouts.
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/exceptions.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace VPContact
{
  namespace
  {
    // The entry of @p cache (most recently used first) that @p matches, moved
    // to the front; if there is none, the one @p make builds, in front, the
    // least recently used dropped beyond @p capacity.
    template <typename Entry, typename Matches, typename Make>
    Entry &
    most_recent(std::vector<std::unique_ptr<Entry>> &cache,
                const std::size_t                    capacity,
                const Matches                       &matches,
                const Make                          &make)
    {
      const auto known = std::find_if(cache.begin(),
                                      cache.end(),
                                      [&](const std::unique_ptr<Entry> &e) {
                                        return matches(*e);
                                      });
      if (known != cache.end())
        {
          std::rotate(cache.begin(), known, known + 1);
          return *cache.front();
        }
      if (cache.size() == capacity)
        cache.pop_back();
      cache.insert(cache.begin(), make());
      return *cache.front();
    }
  } // namespace



  void
  copy_owned_values(const LA::MPI::Vector &from, LA::MPI::Vector &to)
  {
    AssertThrow(from.locally_owned_elements() == to.locally_owned_elements(),
                ExcMessage("copy_owned_values() needs two vectors with the "
                           "same owned entries."));
    std::copy(from.begin(), from.end(), to.begin());
  }



  void
  copy_into_blocks(const LA::MPI::Vector &full, LA::MPI::BlockVector &blocks)
  {
    AssertThrow(full.locally_owned_size() == blocks.locally_owned_size()
                  && !full.has_ghost_elements(),
                ExcMessage("copy_into_blocks() needs an owned vector with "
                           "the owned entries of the blocks."));
    const double *entry = full.begin();
    for (unsigned int b = 0; b < blocks.n_blocks(); ++b)
      {
        std::copy_n(entry,
                    blocks.block(b).locally_owned_size(),
                    blocks.block(b).begin());
        entry += blocks.block(b).locally_owned_size();
      }
  }



  GhostExchange::LayoutPair &
  GhostExchange::pair_for(const Epetra_BlockMap &source,
                          const Epetra_BlockMap &target)
  {
    const auto same_maps = [&](const LayoutPair &p) {
      return p.source_layout->DataPtr() == source.DataPtr()
             && p.target_layout->DataPtr() == target.DataPtr();
    };
    // Layouts not seen (a new mesh, or other vectors): compared in full
    // once, which walks every index.
    const auto make_pair = [&]() {
      auto pair          = std::make_unique<LayoutPair>();
      pair->same_layouts = target.SameAs(source);
      if (!pair->same_layouts)
        pair->importer = std::make_unique<Epetra_Import>(target, source);
      pair->source_layout = std::make_unique<Epetra_BlockMap>(source);
      pair->target_layout = std::make_unique<Epetra_BlockMap>(target);
      return pair;
    };
    return most_recent(pairs, max_pairs, same_maps, make_pair);
  }



  void
  GhostExchange::copy(const LA::MPI::Vector &owned, LA::MPI::Vector &ghosted)
  {
    AssertDimension(owned.size(), ghosted.size());
    const LayoutPair &pair = pair_for(owned.trilinos_vector().Map(),
                                      ghosted.trilinos_vector().Map());
    if (pair.same_layouts)
      {
        std::copy(owned.begin(), owned.end(), ghosted.begin());
        return;
      }
    const int error = ghosted.trilinos_vector().Import(owned.trilinos_vector(),
                                                       *pair.importer,
                                                       Insert);
    AssertThrow(error == 0, ExcTrilinosError(error));
  }


  const GhostExchange::BlockParts &
  GhostExchange::block_parts_for(const LA::MPI::BlockVector &owned,
                                 const LA::MPI::Vector      &ghosted)
  {
    const Epetra_BlockMap &map = ghosted.trilinos_vector().Map();
    return most_recent(
      block_parts,
      max_block_parts,
      [&](const BlockParts &p) {
        return p.ghosted_layout->DataPtr() == map.DataPtr();
      },
      [&]() { return make_block_parts(owned, ghosted); });
  }



  std::unique_ptr<GhostExchange::BlockParts>
  GhostExchange::make_block_parts(const LA::MPI::BlockVector &owned,
                                  const LA::MPI::Vector      &ghosted)
  {
    auto parts = std::make_unique<BlockParts>();
    // The ghosted vector's global indices, in the order of its entries,
    // split at the blocks' bounds; each part must be contiguous.
    const Epetra_BlockMap &map = ghosted.trilinos_vector().Map();
    parts->first_entry.assign(owned.n_blocks() + 1, 0);
    parts->layouts.clear();
    types::global_dof_index block_start = 0;
    std::size_t             entry       = 0;
    const std::size_t       n_entries   = map.NumMyElements();
    for (unsigned int b = 0; b < owned.n_blocks(); ++b)
      {
        const types::global_dof_index block_end
          = block_start + owned.block(b).size();
        parts->first_entry[b] = entry;
        std::vector<types::global_dof_index> indices;
        for (; entry < n_entries
               && static_cast<types::global_dof_index>(map.GID64(entry))
                    < block_end;
             ++entry)
          {
            const auto index
              = static_cast<types::global_dof_index>(map.GID64(entry));
            AssertThrow(index >= block_start
                          && (indices.empty()
                              || index - block_start > indices.back()),
                        ExcMessage("GhostExchange::copy() needs the ghosted "
                                   "vector's entries sorted by index."));
            indices.push_back(index - block_start);
          }
        IndexSet part(owned.block(b).size());
        part.add_indices(indices.begin(), indices.end());
        part.compress();
        // Overlapping on several ranks: the layout lists the entries in
        // the order of the set, the ghosted vector's order. On one rank the
        // part is the whole block, whose linear layout stores no list of
        // its indices (a list for every block of every ghosted layout kept
        // would add to the run's peak memory).
        const MPI_Comm communicator = owned.block(b).get_mpi_communicator();
        parts->layouts.push_back(std::make_unique<Epetra_Map>(
          part.make_trilinos_map(communicator,
                                 Utilities::MPI::n_mpi_processes(communicator)
                                   > 1)));
        block_start = block_end;
      }
    AssertThrow(entry == n_entries, ExcInternalError());
    parts->first_entry.back() = entry;
    parts->ghosted_layout     = std::make_unique<Epetra_BlockMap>(map);
    return parts;
  }



  void
  GhostExchange::copy(const LA::MPI::BlockVector &owned,
                      LA::MPI::Vector            &ghosted)
  {
    AssertDimension(owned.size(), ghosted.size());
    const BlockParts &parts = block_parts_for(owned, ghosted);
    // Each block into a view of its part of the ghosted entries: a copy
    // where the layouts are the same (one rank), else an import kept as
    // for two vectors.
    for (unsigned int b = 0; b < owned.n_blocks(); ++b)
      {
        double *const          part   = ghosted.begin() + parts.first_entry[b];
        const Epetra_BlockMap &layout = *parts.layouts[b];
        const LayoutPair      &pair
          = pair_for(owned.block(b).trilinos_vector().Map(), layout);
        if (pair.same_layouts)
          {
            std::copy(owned.block(b).begin(), owned.block(b).end(), part);
            continue;
          }
        Epetra_Vector view(View, layout, part);
        const int     error = view.Import(owned.block(b).trilinos_vector(),
                                      *pair.importer,
                                      Insert);
        AssertThrow(error == 0, ExcTrilinosError(error));
      }
  }
} // namespace VPContact
