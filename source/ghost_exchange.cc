// GhostExchange: the import of owned entries into a ghosted vector, built
// once per pair of layouts.
#include <vpcontact/ghost_exchange.h>

#include <deal.II/lac/exceptions.h>

#include <algorithm>

namespace VPContact
{
  void
  GhostExchange::copy(const TrilinosWrappers::MPI::Vector &owned,
                      TrilinosWrappers::MPI::Vector       &ghosted)
  {
    AssertDimension(owned.size(), ghosted.size());
    const Epetra_BlockMap &source = owned.trilinos_vector().Map();
    const Epetra_BlockMap &target = ghosted.trilinos_vector().Map();
    if (target.SameAs(source))
      {
        std::copy(owned.begin(), owned.end(), ghosted.begin());
        return;
      }
    if (!importer || !importer->SourceMap().SameAs(source)
        || !importer->TargetMap().SameAs(target))
      importer = std::make_unique<Epetra_Import>(target, source);
    const int error = ghosted.trilinos_vector().Import(owned.trilinos_vector(),
                                                       *importer,
                                                       Insert);
    AssertThrow(error == 0, ExcTrilinosError(error));
  }
} // namespace VPContact
