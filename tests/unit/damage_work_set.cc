// Unit test: DamageWorkSet and SupportProduct::vmult_on(). For x nonzero at
// a few nodes, the work set of their neighbourhoods (and of the rows coupled
// to ghosts) is ascending and without repeats, holds every row that K x
// reaches, and vmult_on() on it gives vmult()'s entries to the bit there
// and leaves the other entries alone. Then growing the set keeps it
// ascending. Serial and on 2 ranks.
#include <vpcontact/damage/damage_work_set.h>
#include <vpcontact/damage/support_product.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <iostream>

#include "q1_pattern_matrix.h"

using namespace VPContact;

namespace
{
  // Ascending without repeats, on every rank.
  bool
  ascending(const std::vector<unsigned int> &positions, const MPI_Comm comm)
  {
    const bool here
      = std::adjacent_find(positions.begin(),
                           positions.end(),
                           [](const unsigned int a, const unsigned int b) {
                             return a >= b;
                           })
        == positions.end();
    return Utilities::MPI::min(here ? 1 : 0, comm) == 1;
  }

  void
  report(const std::string &what, const bool holds, const MPI_Comm comm)
  {
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << what << ": " << (holds ? "yes" : "no") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  const Q1PatternMatrix   q1(comm);
  const IndexSet         &owned = q1.owned;
  const LA::SparseMatrix &K     = q1.K;
  OwnedRows               matrix_rows;
  matrix_rows.reinit(K, owned, comm);
  SupportProduct product;
  product.initialize(matrix_rows);

  // x nonzero at every 13th node; the work set of those it owns.
  LA::MPI::Vector           x(owned, comm), y(owned, comm), y_on(owned, comm);
  std::vector<unsigned int> support;
  for (const auto i : owned)
    if (i % 13 == 0)
      {
        x(i) = 1. + 0.01 * i;
        support.push_back(owned.index_within_set(i));
      }
  x.compress(VectorOperation::insert);
  DamageWorkSet work;
  work.clear(owned.n_elements());
  work.add_neighbourhoods(support, product);
  work.add(product.rows_of_ghosts());
  const std::vector<unsigned int> &rows = work.positions();
  report("work set ascending, no repeats", ascending(rows, comm), comm);

  product.vmult(y, x);
  y_on = 7.;
  product.vmult_on(y_on, x, rows);
  std::vector<bool> in_work(owned.n_elements(), false);
  for (const unsigned int i : rows)
    in_work[i] = true;
  bool same = true, reached_in_work = true, others_left = true;
  for (unsigned int i = 0; i < owned.n_elements(); ++i)
    if (in_work[i])
      same = same && (y.begin()[i] == y_on.begin()[i]);
    else
      {
        reached_in_work = reached_in_work && (y.begin()[i] == 0.);
        others_left     = others_left && (y_on.begin()[i] == 7.);
      }
  report("K x vanishes off the work set",
         Utilities::MPI::min(reached_in_work ? 1 : 0, comm) == 1,
         comm);
  report("vmult_on() equals vmult() to the bit on the work set",
         Utilities::MPI::min(same ? 1 : 0, comm) == 1,
         comm);
  report("vmult_on() leaves the other entries alone",
         Utilities::MPI::min(others_left ? 1 : 0, comm) == 1,
         comm);

  // Growing the set: the neighbourhoods of every 5th position (some already
  // in it) keep it ascending, and it holds them.
  std::vector<unsigned int> more;
  for (unsigned int i = 0; i < owned.n_elements(); i += 5)
    more.push_back(i);
  const std::size_t before = rows.size();
  work.add_neighbourhoods(more, product);
  bool holds = true;
  for (const unsigned int i : more)
    holds = holds && std::binary_search(rows.begin(), rows.end(), i);
  report("grown set ascending, no repeats", ascending(rows, comm), comm);
  report("grown set holds the new positions and is larger",
         Utilities::MPI::min(holds && rows.size() > before ? 1 : 0, comm) == 1,
         comm);

  // A few positions at a time (merged into the list rather than read back
  // from the marks): the last node's neighbourhood, then the first's.
  DamageWorkSet small;
  small.clear(owned.n_elements());
  const unsigned int last = owned.n_elements() - 1;
  small.add_neighbourhoods({last}, product);
  small.add_neighbourhoods({0u}, product);
  const std::vector<unsigned int> &few = small.positions();
  bool both = std::binary_search(few.begin(), few.end(), last)
              && std::binary_search(few.begin(), few.end(), 0u)
              && few.size() < owned.n_elements() / 4;
  for (const unsigned int p : {0u, last})
    for (const unsigned int row : product.rows_of_owned(p))
      both = both && std::binary_search(few.begin(), few.end(), row);
  report("few positions merged: ascending, no repeats",
         ascending(few, comm),
         comm);
  report(
    "few positions merged: both neighbourhoods, under a quarter of the nodes",
    Utilities::MPI::min(both ? 1 : 0, comm) == 1,
    comm);
}
