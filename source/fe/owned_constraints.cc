// distribute_constraints(): AffineConstraints::distribute() on the owned
// entries in place where the constraints read only those.
#include <vpcontact/fe/owned_constraints.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

namespace VPContact
{
  void
  distribute_constraints(const AffineConstraints<double> &constraints,
                         LA::MPI::Vector                 &vector)
  {
    Assert(!vector.has_ghost_elements(),
           ExcMessage("distribute_constraints() writes an owned vector."));
    const IndexSet owned            = vector.locally_owned_elements();
    bool           reads_only_owned = true;
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        for (const auto &entry : line.entries)
          reads_only_owned = reads_only_owned && owned.is_element(entry.first);
    if (Utilities::MPI::min(reads_only_owned ? 1u : 0u,
                            vector.get_mpi_communicator())
        == 0)
      {
        constraints.distribute(vector);
        return;
      }
    distribute_owned_constraints(constraints, vector);
  }



  void
  distribute_owned_constraints(const AffineConstraints<double> &constraints,
                               LA::MPI::Vector                 &vector)
  {
    const IndexSet owned  = vector.locally_owned_elements();
    double        *values = vector.begin();
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          double value = line.inhomogeneity;
          for (const auto &entry : line.entries)
            value += entry.second * values[owned.index_within_set(entry.first)];
          values[owned.index_within_set(line.index)] = value;
        }
  }
} // namespace VPContact
