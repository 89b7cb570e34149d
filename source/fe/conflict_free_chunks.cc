// ConflictFreeChunks: the plan of chunks and colors for adding cell vectors
// from several threads at once (see conflict_free_chunks.h).
#include <vpcontact/fe/conflict_free_chunks.h>

#include <algorithm>
#include <utility>

namespace VPContact
{
  std::vector<types::global_dof_index>
  ConflictFreeChunks::constrained_entries(
    const AffineConstraints<double> &constraints)
  {
    std::vector<types::global_dof_index> entries;
    entries.reserve(constraints.n_constraints());
    for (const auto &line : constraints.get_lines())
      entries.push_back(line.index);
    std::sort(entries.begin(), entries.end());
    return entries;
  }



  bool
  ConflictFreeChunks::outdated(
    const std::size_t                cells,
    const AffineConstraints<double> &constraints) const
  {
    return !made || cells != n_cells
           || constrained_entries(constraints) != constrained;
  }



  void
  ConflictFreeChunks::reinit(const std::size_t                cells,
                             const CellIndices               &cell_indices,
                             const types::global_dof_index    first_owned,
                             const types::global_dof_index    n_owned,
                             const AffineConstraints<double> &constraints,
                             const unsigned int               chunk_size)
  {
    // Each cell's positions, and whether it is plain.
    constrained = constrained_entries(constraints);
    n_cells     = cells;
    std::vector<bool>                    plain(cells, true);
    std::vector<types::global_dof_index> indices;
    for (std::size_t i = 0; i < cells; ++i)
      {
        cell_indices(i, indices);
        if (i == 0)
          {
            n_entries = indices.size();
            cell_positions.assign(cells * n_entries, 0);
          }
        for (unsigned int a = 0; a < n_entries; ++a)
          {
            const auto index = indices[a];
            plain[i]         = plain[i] && index >= first_owned
                       && index < first_owned + n_owned
                       && !std::binary_search(constrained.begin(),
                                              constrained.end(),
                                              index);
            cell_positions[i * n_entries + a]
              = (plain[i] ? index - first_owned : 0);
          }
      }
    make_chunks(plain, chunk_size);
  }



  void
  ConflictFreeChunks::reinit(std::vector<unsigned int> &&positions,
                             const unsigned int          entries,
                             const std::vector<bool>    &plain,
                             const unsigned int          chunk_size)
  {
    AssertThrow(positions.size() == plain.size() * entries, ExcInternalError());
    constrained.clear();
    n_cells        = plain.size();
    n_entries      = entries;
    cell_positions = std::move(positions);
    make_chunks(plain, chunk_size);
  }



  void
  ConflictFreeChunks::make_chunks(const std::vector<bool> &plain,
                                  const unsigned int       chunk_size)
  {
    const unsigned int n_chunks
      = std::max<std::size_t>(1, (n_cells + chunk_size - 1) / chunk_size);
    chunk_cells.assign(n_chunks, {});
    others.clear();
    for (std::size_t i = 0; i < n_cells; ++i)
      if (plain[i])
        chunk_cells[i / chunk_size].push_back(i);
      else
        others.push_back(i);
    color_chunks_greedily(n_chunks);
    made = true;
  }



  void
  ConflictFreeChunks::color_chunks_greedily(const unsigned int n_chunks)
  {
    // Two chunks conflict when plain cells of both add to one entry: the
    // pairs (entry, chunk), sorted by entry, name them. Each chunk, in
    // order, takes the smallest color none of its conflicting chunks has.
    std::vector<std::pair<unsigned int, unsigned int>> touches;
    for (unsigned int c = 0; c < n_chunks; ++c)
      for (const std::size_t i : chunk_cells[c])
        for (unsigned int a = 0; a < n_entries; ++a)
          touches.emplace_back(cell_positions[i * n_entries + a], c);
    std::sort(touches.begin(), touches.end());
    touches.erase(std::unique(touches.begin(), touches.end()), touches.end());
    std::vector<std::vector<unsigned int>> conflicts(n_chunks);
    for (std::size_t first = 0; first < touches.size();)
      {
        std::size_t last = first;
        while (last < touches.size()
               && touches[last].first == touches[first].first)
          ++last;
        for (std::size_t p = first; p < last; ++p)
          for (std::size_t q = first; q < last; ++q)
            if (p != q)
              conflicts[touches[p].second].push_back(touches[q].second);
        first = last;
      }

    std::vector<unsigned int> color(n_chunks, 0);
    color_chunks.clear();
    for (unsigned int c = 0; c < n_chunks; ++c)
      {
        std::vector<bool> taken(color_chunks.size() + 1, false);
        for (const unsigned int other : conflicts[c])
          if (other < c)
            taken[color[other]] = true;
        color[c] = std::find(taken.begin(), taken.end(), false) - taken.begin();
        if (color[c] == color_chunks.size())
          color_chunks.emplace_back();
        color_chunks[color[c]].push_back(c);
      }
  }
} // namespace VPContact
