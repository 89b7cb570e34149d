// OwnedLayout: vectors on a rank's own degrees of freedom, in one kept
// layout where the indices are several ranges.
#include <vpcontact/linear_algebra/owned_layout.h>

namespace VPContact
{
  void
  OwnedLayout::reinit(const IndexSet &owned_dofs, MPI_Comm comm)
  {
    owned        = owned_dofs;
    communicator = comm;
    kept.clear();
  }



  void
  OwnedLayout::make(LA::MPI::Vector &vector) const
  {
    if (owned.is_contiguous())
      {
        vector.reinit(owned, communicator);
        return;
      }
    if (kept.size() == 0)
      kept.reinit(owned, communicator);
    vector.reinit(kept);
  }
} // namespace VPContact
