// Whether a distributed vector holds only finite numbers, checked entry by
// entry: a norm would overflow for large finite entries (its squares) or
// skip a NaN (a maximum), and call a sound vector broken or a broken one
// sound.
#ifndef vpcontact_finite_values_h
#define vpcontact_finite_values_h

#include <deal.II/base/mpi.h>

#include <cmath>

namespace VPContact
{
  /// Collective: whether every locally owned entry of @p v on every rank of
  /// @p communicator is finite.
  template <typename VectorType>
  bool
  all_finite(const VectorType &v, const MPI_Comm communicator)
  {
    bool finite = true;
    for (const double value : v)
      finite = finite && std::isfinite(value);
    return !dealii::Utilities::MPI::logical_or(!finite, communicator);
  }
} // namespace VPContact

#endif
