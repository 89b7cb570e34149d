// Unit test: GhostExchange copies an owned vector into a ghosted one, owned
// and ghost entries alike, serial and on 2 ranks. Entry i of the owned vector
// is i + 0.5 (then 2 i + 0.25 in a second copy with the kept import); every
// rank owns a contiguous half and reads a band of its neighbour's entries as
// ghosts. Then the ghosted vector gets a wider band (a new layout), and the
// exchange must notice and build a new import. The exchange then serves two
// owned vectors with layouts of their own in turn (it keeps both pairs), and
// copy_owned_values() copies between two such owned vectors. Last, two
// vectors of two blocks each go in turn into two ghosted vectors on all
// their entries, as the displacement's increment and solution do in every
// step (the exchange keeps the block parts of both ghosted layouts).
#include <vpcontact/linear_algebra/ghost_exchange.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <string>

using namespace VPContact;

namespace
{
  // The largest |ghosted(i) - value(i)| over the entries this rank holds,
  // over all ranks.
  template <typename Value>
  double
  largest_error(const LA::MPI::Vector &ghosted,
                const IndexSet        &relevant,
                const Value           &value,
                const MPI_Comm         comm)
  {
    double error = 0;
    for (const auto i : relevant)
      error = std::max(error, std::abs(ghosted(i) - value(i)));
    return Utilities::MPI::max(error, comm);
  }

  // Two vectors of two blocks (each block owned like @p owned), copied in
  // turn into two ghosted vectors on both blocks with ghost bands of 3 and
  // 5 entries; the largest error over three rounds.
  template <typename Band>
  double
  block_copies_in_turn(const IndexSet &owned,
                       const Band     &relevant_with_band,
                       const MPI_Comm  comm)
  {
    const unsigned int   n = owned.size();
    LA::MPI::BlockVector a(std::vector<IndexSet>{owned, owned}, comm);
    LA::MPI::BlockVector b(std::vector<IndexSet>{owned, owned}, comm);
    for (unsigned int block = 0; block < 2; ++block)
      for (const auto i : owned)
        {
          a.block(block)[i] = (block + 1) * n + i;
          b.block(block)[i] = -1. - (block + 1) * n - i;
        }
    a.compress(VectorOperation::insert);
    b.compress(VectorOperation::insert);
    const auto on_both = [&](const IndexSet &part) {
      IndexSet both(2 * n);
      both.add_indices(part);
      both.add_indices(part, n);
      return both;
    };
    const IndexSet  relevant_a = on_both(relevant_with_band(3));
    const IndexSet  relevant_b = on_both(relevant_with_band(5));
    LA::MPI::Vector ghosted_a(on_both(owned), relevant_a, comm);
    LA::MPI::Vector ghosted_b(on_both(owned), relevant_b, comm);
    // Entry j of a vector on both blocks is entry j % n of block j / n.
    const auto    value_a = [n](const unsigned int j) { return 1. * n + j; };
    const auto    value_b = [n](const unsigned int j) { return -1. - n - j; };
    GhostExchange exchange;
    double        error = 0;
    for (unsigned int round = 0; round < 3; ++round)
      {
        exchange.copy(a, ghosted_a);
        error = std::max(error,
                         largest_error(ghosted_a, relevant_a, value_a, comm));
        exchange.copy(b, ghosted_b);
        error = std::max(error,
                         largest_error(ghosted_b, relevant_b, value_b, comm));
      }
    return error;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int n_ranks            = Utilities::MPI::n_mpi_processes(comm);
  const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
  const unsigned int n     = 40;
  const unsigned int chunk = n / n_ranks;

  IndexSet owned(n);
  owned.add_range(rank * chunk, (rank + 1) * chunk);
  // The owned range and `band` entries on each side (the neighbours' own).
  const auto relevant_with_band = [&](const unsigned int band) {
    IndexSet relevant(n);
    relevant.add_range(rank * chunk >= band ? rank * chunk - band : 0,
                       std::min(n, (rank + 1) * chunk + band));
    return relevant;
  };

  LA::MPI::Vector owned_vector(owned, comm);
  GhostExchange   exchange;
  const auto      report = [&](const std::string &what, const double error) {
    if (rank == 0)
      std::printf("%s: largest error %s\n",
                  what.c_str(),
                  error == 0. ? "0" : std::to_string(error).c_str());
  };

  const auto first  = [](const unsigned int i) { return i + 0.5; };
  const auto second = [](const unsigned int i) { return 2. * i + 0.25; };

  IndexSet        relevant = relevant_with_band(3);
  LA::MPI::Vector ghosted(owned, relevant, comm);
  for (const auto i : owned)
    owned_vector[i] = first(i);
  owned_vector.compress(VectorOperation::insert);
  exchange.copy(owned_vector, ghosted);
  report("first copy", largest_error(ghosted, relevant, first, comm));

  for (const auto i : owned)
    owned_vector[i] = second(i);
  owned_vector.compress(VectorOperation::insert);
  exchange.copy(owned_vector, ghosted);
  report("second copy, same layouts",
         largest_error(ghosted, relevant, second, comm));

  relevant = relevant_with_band(7);
  LA::MPI::Vector wider(owned, relevant, comm);
  exchange.copy(owned_vector, wider);
  report("into a wider ghosted layout",
         largest_error(wider, relevant, second, comm));

  // A second owned vector, initialized on its own from the same index set,
  // copied into the same ghosted vector in turn with the first.
  LA::MPI::Vector other_owned(owned, comm);
  const auto      third = [](const unsigned int i) { return 3. * i - 1.; };
  for (const auto i : owned)
    other_owned[i] = third(i);
  other_owned.compress(VectorOperation::insert);
  double error = 0.;
  for (unsigned int round = 0; round < 3; ++round)
    {
      exchange.copy(other_owned, wider);
      error = std::max(error, largest_error(wider, relevant, third, comm));
      exchange.copy(owned_vector, wider);
      error = std::max(error, largest_error(wider, relevant, second, comm));
    }
  report("two owned vectors in turn", error);

  LA::MPI::Vector copy(owned, comm);
  copy_owned_values(other_owned, copy);
  error = 0.;
  for (const auto i : owned)
    error = std::max(error, std::abs(copy[i] - third(i)));
  report("copy_owned_values", Utilities::MPI::max(error, comm));

  report("block vectors into two ghosted layouts in turn",
         block_copies_in_turn(owned, relevant_with_band, comm));
}
