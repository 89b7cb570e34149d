// Vectors on a rank's own degrees of freedom, made in one layout that is
// kept where making a layout is costly.
#ifndef vpcontact_owned_layout_h
#define vpcontact_owned_layout_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/index_set.h>

#include <mpi.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * Makes vectors on the degrees of freedom a rank owns (no ghosts).
   *
   * Where these form one range of indices (one rank, or one block), the
   * layout of a new vector costs nothing, and make() builds each vector
   * from the index set. Where they are several ranges (the blocks of a
   * system on several ranks), Epetra builds for every new layout a table of
   * its indices, and compress() and a ghost import in it a directory of
   * their owners: there make() gives every vector the layout of one vector
   * kept for the purpose (the rank's entries once more in memory), made at
   * the first call after reinit().
   */
  class OwnedLayout
  {
  public:
    /// Vectors on @p owned from now on; forgets the kept layout.
    void
    reinit(const IndexSet &owned, MPI_Comm communicator);

    /// @p vector on the owned degrees of freedom, zero.
    void
    make(LA::MPI::Vector &vector) const;

  private:
    IndexSet owned;
    MPI_Comm communicator = MPI_COMM_SELF;
    /// The kept layout (several ranges only), empty until make() needs it.
    mutable LA::MPI::Vector kept;
  };
} // namespace VPContact

#endif
