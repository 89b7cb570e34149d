// The split of a Cholesky factor's supernodes into two groups of
// independent subtrees and the top above them.
#include <vpcontact/supernode_partition.h>

#include <algorithm>
#include <cmath>

namespace VPContact
{
  namespace
  {
    /// The elimination tree of the supernodes: each one's parent (or -1),
    /// the first supernode of its subtree, and the work (stored entries) of
    /// the subtree. Returns false if the numbering is not a postorder.
    bool
    supernodal_tree(const cholmod_factor &factor,
                    std::vector<long>    &parent,
                    std::vector<long>    &first,
                    std::vector<double>  &subtree_work)
    {
      const long       *super   = static_cast<const long *>(factor.super);
      const long       *pi      = static_cast<const long *>(factor.pi);
      const long       *rows    = static_cast<const long *>(factor.s);
      const long        n_super = static_cast<long>(factor.nsuper);
      std::vector<long> supernode_of_column(factor.n);
      for (long s = 0; s < n_super; ++s)
        std::fill(supernode_of_column.begin() + super[s],
                  supernode_of_column.begin() + super[s + 1],
                  s);
      parent.assign(n_super, -1);
      first.resize(n_super);
      subtree_work.resize(n_super);
      for (long s = 0; s < n_super; ++s)
        {
          const long n_cols = super[s + 1] - super[s];
          const long n_rows = pi[s + 1] - pi[s];
          subtree_work[s]   = static_cast<double>(n_cols) * n_rows;
          first[s]          = s;
          if (n_rows > n_cols)
            parent[s] = supernode_of_column[rows[pi[s] + n_cols]];
        }
      // Children come before their parents; then each subtree starts where
      // its first child's subtree starts.
      for (long s = 0; s < n_super; ++s)
        if (parent[s] >= 0)
          {
            if (parent[s] <= s)
              return false;
            subtree_work[parent[s]] += subtree_work[s];
            first[parent[s]] = std::min(first[parent[s]], first[s]);
          }
      // A postorder: the subtrees of the children of p tile [first[p], p).
      for (long p = 0; p < n_super; ++p)
        {
          long c = p - 1;
          while (c >= first[p])
            {
              if (parent[c] != p)
                return false;
              c = first[c] - 1;
            }
        }
      return true;
    }



    /// The children of @p p, from the postorder ranges.
    std::vector<long>
    children(const std::vector<long> &first, const long p)
    {
      std::vector<long> result;
      for (long c = p - 1; c >= first[p]; c = first[c] - 1)
        result.push_back(c);
      return result;
    }



    /// The subtrees of @p frontier put into two groups, heaviest first,
    /// each into the lighter group; returns the work of both.
    std::array<double, 2>
    fill_groups(std::vector<long>                &frontier,
                const std::vector<double>        &work,
                std::array<std::vector<long>, 2> &groups)
    {
      std::sort(frontier.begin(), frontier.end(), [&](long a, long b) {
        return work[a] > work[b] || (work[a] == work[b] && a < b);
      });
      std::array<double, 2> load = {{0., 0.}};
      groups[0].clear();
      groups[1].clear();
      for (const long s : frontier)
        {
          const unsigned int g = (load[0] <= load[1] ? 0 : 1);
          load[g] += work[s];
          groups[g].push_back(s);
        }
      return load;
    }
  } // namespace



  SupernodePartition::SupernodePartition(const cholmod_factor &factor)
  {
    const long          n_super = static_cast<long>(factor.nsuper);
    const long         *super   = static_cast<const long *>(factor.super);
    const long         *pi      = static_cast<const long *>(factor.pi);
    const long         *rows    = static_cast<const long *>(factor.s);
    std::vector<long>   parent, first;
    std::vector<double> work;
    const auto          sequential = [&]() {
      groups[0].assign(1, {0, n_super - 1});
      groups[1].clear();
      top.clear();
      top_columns.clear();
      top_slot.assign(factor.n, -1);
      rows_below_before_top.resize(n_super);
      for (long s = 0; s < n_super; ++s)
        rows_below_before_top[s]
          = (pi[s + 1] - pi[s]) - (super[s + 1] - super[s]);
    };
    if (n_super == 0 || !supernodal_tree(factor, parent, first, work))
      {
        sequential();
        return;
      }

    // Take the heaviest subtree's root into the top until the groups are
    // within 5 % of each other, or the top holds a fifth of the work.
    std::vector<long> frontier;
    for (long s = 0; s < n_super; ++s)
      if (parent[s] < 0)
        frontier.push_back(s);
    double total = 0;
    for (const long s : frontier)
      total += work[s];
    std::array<std::vector<long>, 2> roots;
    double                           top_work = 0;
    for (unsigned int expansion = 0;; ++expansion)
      {
        const auto load = fill_groups(frontier, work, roots);
        if (std::abs(load[0] - load[1]) <= 0.05 * total || expansion == 64
            || top_work > 0.2 * total)
          break;
        const long heaviest = frontier.front();
        frontier.erase(frontier.begin());
        top.push_back(heaviest);
        const long n_cols = super[heaviest + 1] - super[heaviest];
        top_work
          += static_cast<double>(n_cols) * (pi[heaviest + 1] - pi[heaviest]);
        for (const long c : children(first, heaviest))
          frontier.push_back(c);
      }
    std::sort(top.begin(), top.end());
    for (unsigned int g = 0; g < 2; ++g)
      {
        std::sort(roots[g].begin(), roots[g].end());
        for (const long r : roots[g])
          groups[g].emplace_back(first[r], r);
      }

    top_slot.assign(factor.n, -1);
    for (const long t : top)
      for (long c = super[t]; c < super[t + 1]; ++c)
        {
          top_slot[c] = static_cast<int>(top_columns.size());
          top_columns.push_back(c);
        }
    // The rows below a supernode are sorted, and the top's supernodes
    // come after every subtree below them, so the rows of the top come
    // last. Checked here rather than assumed.
    rows_below_before_top.resize(n_super);
    for (long s = 0; s < n_super; ++s)
      {
        const long  n_cols  = super[s + 1] - super[s];
        const long *below   = rows + pi[s] + n_cols;
        const long  n_below = (pi[s + 1] - pi[s]) - n_cols;
        const bool  in_top  = top_slot[super[s]] >= 0;
        long        k       = 0;
        while (k < n_below && top_slot[below[k]] < 0)
          ++k;
        bool top_rows_last = !(in_top && k != 0);
        for (long i = k; i < n_below; ++i)
          top_rows_last = top_rows_last && top_slot[below[i]] >= 0;
        if (!top_rows_last)
          {
            sequential();
            return;
          }
        rows_below_before_top[s] = (in_top ? n_below : k);
      }
  }
} // namespace VPContact
