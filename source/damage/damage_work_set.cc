// DamageWorkSet: the owned damage nodes a damage solve of the step can
// change, kept ascending.
#include <vpcontact/damage/damage_work_set.h>

#include <algorithm>

namespace VPContact
{
  void
  DamageWorkSet::clear(const unsigned int n_owned)
  {
    member.assign(n_owned, false);
    list.clear();
    added.clear();
  }



  void
  DamageWorkSet::add(const std::vector<unsigned int> &positions)
  {
    for (const unsigned int p : positions)
      insert(p);
    merge_added();
  }



  void
  DamageWorkSet::add_neighbourhoods(const std::vector<unsigned int> &positions,
                                    const SupportProduct            &product)
  {
    // The rows of a column hold the position itself (the diagonal entry is
    // part of the pattern), but a hanging node's row may hold nothing else:
    // add the position on its own too.
    for (const unsigned int p : positions)
      {
        insert(p);
        for (const unsigned int row : product.rows_of_owned(p))
          insert(row);
      }
    merge_added();
  }



  const std::vector<unsigned int> &
  DamageWorkSet::positions() const
  {
    return list;
  }



  void
  DamageWorkSet::merge_added()
  {
    // The positions added are few beside the list, except in the first
    // call of a step: few are sorted and merged (one pass over the list),
    // many are read back from the marks in order (one pass over them).
    if (added.empty())
      return;
    if (16 * added.size() > member.size())
      {
        list.clear();
        for (unsigned int p = 0; p < member.size(); ++p)
          if (member[p])
            list.push_back(p);
      }
    else
      {
        std::sort(added.begin(), added.end());
        const auto middle = static_cast<std::ptrdiff_t>(list.size());
        list.insert(list.end(), added.begin(), added.end());
        std::inplace_merge(list.begin(), list.begin() + middle, list.end());
      }
    added.clear();
  }
} // namespace VPContact
