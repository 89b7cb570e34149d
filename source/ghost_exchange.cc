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
    // The layouts are compared in full only when either vector's layout
    // data are not those of the last call (a new mesh, or other vectors):
    // a full comparison walks every index.
    if (!source_layout || source_layout->DataPtr() != source.DataPtr()
        || target_layout->DataPtr() != target.DataPtr())
      {
        same_layouts = target.SameAs(source);
        importer.reset();
        if (!same_layouts)
          importer = std::make_unique<Epetra_Import>(target, source);
        source_layout = std::make_unique<Epetra_BlockMap>(source);
        target_layout = std::make_unique<Epetra_BlockMap>(target);
      }
    if (same_layouts)
      {
        std::copy(owned.begin(), owned.end(), ghosted.begin());
        return;
      }
    const int error = ghosted.trilinos_vector().Import(owned.trilinos_vector(),
                                                       *importer,
                                                       Insert);
    AssertThrow(error == 0, ExcTrilinosError(error));
  }
} // namespace VPContact
