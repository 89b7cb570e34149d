// Unit test: the front of the upper damage set and the rings freed ahead of
// it (DamageBounds::begin_step(), free_ahead_of_front(), rings_moved()). On
// the Q1 damage matrix of a 16 x 16 grid, every node is put at the upper
// bound but a seed; freeing r rings ahead must free exactly the nodes
// within r grid steps of the seed (the square of side 2r + 1 around it, cut
// by the boundary), the front at the start being the 8 (or, at a corner,
// 3) neighbours of the seed. On one rank the front and the rings come from
// the matrix graph, on two from a matrix-vector product each (the rows cut
// into halves between y = 8 and 9, so the rings cross to the other rank):
// both must print the same.
//
// On one rank the front is found anew only near where the sets changed
// since the last call. One DamageBounds taken through a sequence of sets
// that grow, shrink and change at random must then free the same nodes at
// each step as a new DamageBounds given the same sets, which tests every
// node.
#include <vpcontact/damage/damage_bounds.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <iostream>

#include "damage_matrix_tools.h"

using namespace VPContact;
using namespace VPContact::DamageMatrixTools;

namespace
{
  constexpr unsigned int n = 16, nodes = (n + 1) * (n + 1);
  constexpr double       k = 0.01;

  // The grid distance max(|dx|, |dy|) between nodes a and b.
  unsigned int
  distance(const unsigned int a, const unsigned int b)
  {
    const int dx
      = static_cast<int>(a % (n + 1)) - static_cast<int>(b % (n + 1));
    const int dy
      = static_cast<int>(a / (n + 1)) - static_cast<int>(b / (n + 1));
    return std::max(std::abs(dx), std::abs(dy));
  }

  // All nodes upper but @p seed, then @p rings rings freed ahead; prints
  // what was freed and how far from the seed the free and the upper nodes
  // lie.
  void
  check(const LA::SparseMatrix &matrix,
        const IndexSet         &owned,
        const IndexSet         &relevant,
        const unsigned int      seed,
        const unsigned int      rings)
  {
    const MPI_Comm  comm = matrix.get_mpi_communicator();
    LA::MPI::Vector mass(owned, relevant, comm);
    LA::MPI::Vector residual(mass), damage(mass);
    {
      // Upper: zeta = 1 with a positive multiplier; the seed: zeta = 1/2
      // with none.
      LA::MPI::Vector m(owned, comm), r(owned, comm), z(owned, comm);
      for (const auto i : owned)
        {
          m(i) = 1. / (n * n);
          r(i) = (i == seed ? 0. : 1.);
          z(i) = (i == seed ? 0.5 : 1.);
        }
      mass     = m;
      residual = r;
      damage   = z;
    }
    DamageBounds bounds;
    bounds.setup(relevant, owned, mass, comm);
    bounds.update(residual, damage, k);
    OwnedRows rows;
    rows.reinit(matrix, owned, comm);
    SupportProduct product;
    product.initialize(rows);
    bounds.begin_step(product);
    const unsigned int freed      = bounds.free_ahead_of_front(product, rings);
    const auto [n_lower, n_upper] = bounds.count();
    const double rings_moved      = bounds.rings_moved();

    // The sets by node, and the distances from the seed.
    LA::MPI::Vector state(owned, comm);
    bounds.write_state(state);
    unsigned int farthest_free = 0, nearest_upper = n + 1;
    for (const auto i : owned)
      if (state(i) == 1.)
        nearest_upper = std::min(nearest_upper, distance(i, seed));
      else
        farthest_free = std::max(farthest_free, distance(i, seed));
    farthest_free = Utilities::MPI::max(farthest_free, comm);
    nearest_upper = Utilities::MPI::min(nearest_upper, comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "seed (" << seed % (n + 1) << ", " << seed / (n + 1) << "), "
                << rings << " rings: " << freed << " nodes freed, rings moved "
                << rings_moved << ", upper " << n_upper << ", lower " << n_lower
                << "; free nodes at most " << farthest_free
                << " steps from the seed, upper ones at least " << nearest_upper
                << std::endl;
  }

  // The sets of step @p s: around @p seed, nodes within s - 1 steps are
  // lower, free or (now and then) upper again, those at s steps free or
  // upper, the rest upper; "at random" is a fixed hash of node and step.
  void
  set_sets(DamageBounds      &bounds,
           const IndexSet    &owned,
           const IndexSet    &relevant,
           const unsigned int seed,
           const unsigned int s)
  {
    const MPI_Comm  comm = MPI_COMM_WORLD;
    LA::MPI::Vector state(owned, comm);
    for (const auto i : owned)
      {
        const unsigned int d    = distance(i, seed);
        const unsigned int hash = (i * 2654435761u + s * 40503u) >> 7;
        double             set  = 1.;
        if (d + 1 <= s)
          set = (hash % 5 == 0 ? 1. : hash % 3 == 0 ? -1. : 0.);
        else if (d == s)
          set = (hash % 2 == 0 ? 0. : 1.);
        state(i) = set;
      }
    LA::MPI::Vector ghosted(owned, relevant, comm);
    ghosted = state;
    bounds.read_state(ghosted);
  }

  void
  check_incremental(const LA::SparseMatrix &matrix,
                    const IndexSet         &owned,
                    const IndexSet         &relevant,
                    const unsigned int      seed)
  {
    const MPI_Comm  comm = matrix.get_mpi_communicator();
    LA::MPI::Vector mass(owned, relevant, comm);
    {
      LA::MPI::Vector m(owned, comm);
      m    = 1. / (n * n);
      mass = m;
    }
    OwnedRows rows;
    rows.reinit(matrix, owned, comm);
    SupportProduct product;
    product.initialize(rows);
    DamageBounds kept;
    kept.setup(relevant, owned, mass, comm);
    const unsigned int steps[] = {0, 1, 2, 3, 5, 4, 4, 7, 2, 9, 12};
    unsigned int       n_same  = 0;
    for (unsigned int t = 0; t < std::size(steps); ++t)
      {
        const unsigned int rings = 1 + t % 3;
        DamageBounds       fresh;
        fresh.setup(relevant, owned, mass, comm);
        unsigned int freed[2];
        double       moved[2];
        unsigned int index = 0;
        for (DamageBounds *bounds : {&kept, &fresh})
          {
            set_sets(*bounds, owned, relevant, seed, steps[t]);
            bounds->begin_step(product);
            freed[index]   = bounds->free_ahead_of_front(product, rings);
            moved[index++] = bounds->rings_moved();
          }
        LA::MPI::Vector state_kept(owned, comm), state_fresh(owned, comm);
        kept.write_state(state_kept);
        fresh.write_state(state_fresh);
        state_kept -= state_fresh;
        const bool same = (freed[0] == freed[1] && moved[0] == moved[1]
                           && state_kept.linfty_norm() == 0.);
        n_same += same;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            std::cout << "  sets of step " << steps[t] << ", " << rings
                      << " rings: " << freed[0] << " nodes freed, rings moved "
                      << moved[0];
            if (!same)
              std::cout << " (new bounds: " << freed[1] << ", " << moved[1]
                        << ")";
            std::cout << std::endl;
          }
      }
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "kept against fresh bounds: " << n_same << " of "
                << std::size(steps) << " steps the same" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  const DenseMatrix K     = q1_damage_matrix(n, 0.01, k);
  const IndexSet    owned = contiguous_rows(nodes, comm);
  IndexSet          relevant(nodes);
  for (const auto i : owned)
    for (unsigned int j = 0; j < nodes; ++j)
      if (K[i][j] != 0.)
        relevant.add_index(j);
  LA::SparseMatrix matrix;
  copy_to_trilinos(K, owned, comm, matrix);

  // The centre (8, 8), next to the cut between the ranks; a corner; and
  // as many rings as reach the boundary from the centre, and beyond.
  const unsigned int centre = 8 * (n + 1) + 8;
  check(matrix, owned, relevant, centre, 0);
  check(matrix, owned, relevant, centre, 1);
  check(matrix, owned, relevant, centre, 3);
  check(matrix, owned, relevant, 0, 2);
  check(matrix, owned, relevant, centre, 8);
  check(matrix, owned, relevant, centre, 9);
  check_incremental(matrix, owned, relevant, centre);
  check_incremental(matrix, owned, relevant, 2 * (n + 1) + 13);
}
