// GhostExchange: the import of owned entries into a ghosted vector, built
// once per pair of layouts.
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/lac/exceptions.h>

#include <algorithm>

namespace VPContact
{
  void
  copy_owned_values(const LA::MPI::Vector &from, LA::MPI::Vector &to)
  {
    AssertThrow(from.locally_owned_elements() == to.locally_owned_elements(),
                ExcMessage("copy_owned_values() needs two vectors with the "
                           "same owned entries."));
    std::copy(from.begin(), from.end(), to.begin());
  }



  GhostExchange::LayoutPair &
  GhostExchange::pair_for(const Epetra_BlockMap &source,
                          const Epetra_BlockMap &target)
  {
    const auto known
      = std::find_if(pairs.begin(),
                     pairs.end(),
                     [&](const std::unique_ptr<LayoutPair> &p) {
                       return p->source_layout->DataPtr() == source.DataPtr()
                              && p->target_layout->DataPtr()
                                   == target.DataPtr();
                     });
    if (known != pairs.end())
      {
        std::rotate(pairs.begin(), known, known + 1);
        return *pairs.front();
      }

    // Layouts not seen (a new mesh, or other vectors): compared in full
    // once, which walks every index.
    auto pair          = std::make_unique<LayoutPair>();
    pair->same_layouts = target.SameAs(source);
    if (!pair->same_layouts)
      pair->importer = std::make_unique<Epetra_Import>(target, source);
    pair->source_layout = std::make_unique<Epetra_BlockMap>(source);
    pair->target_layout = std::make_unique<Epetra_BlockMap>(target);
    if (pairs.size() == max_pairs)
      pairs.pop_back();
    pairs.insert(pairs.begin(), std::move(pair));
    return *pairs.front();
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
} // namespace VPContact
