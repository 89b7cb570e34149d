// Unit test: ConflictFreeChunks plans the right-hand side's threads so that
// the result is the serial assembly's. A Q1 vector field on a unit square
// with a corner refined twice (hanging nodes) and a Dirichlet side, on 1
// and 2 ranks, in chunks of 8 cells: every cell is planned once; a plain
// cell has only owned, unconstrained entries; no two chunks of a color
// share an entry; cell vectors added color by color in threads, the other
// cells through the constraints, give what distribute_local_to_global
// gives for all cells (to round-off), and the same bits with 1 and 2
// threads; a new constraint makes the plan outdated. The plan made from
// the cells' positions in a vector of owned and ghost entries (the error
// estimator's) plans every cell once, without a shared position in a color.
#include <vpcontact/fe/conflict_free_chunks.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/function.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parallel.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "corner_refined_mesh.h"

using namespace VPContact;

namespace
{
  using Cells = std::vector<DoFHandler<2>::active_cell_iterator>;

  /// An arbitrary vector of cell @p i.
  Vector<double>
  cell_vector(const std::size_t i, const unsigned int n)
  {
    Vector<double> v(n);
    for (unsigned int a = 0; a < n; ++a)
      v(a) = std::sin(0.7 * i + 1.3 * a) + 0.1 * a;
    return v;
  }

  /// The assembly by the plan: colors in threads, then the other cells.
  void
  assemble_by_plan(const ConflictFreeChunks        &plan,
                   const Cells                     &cells,
                   const AffineConstraints<double> &constraints,
                   LA::MPI::Vector                 &vector)
  {
    vector                   = 0.;
    double *const      local = vector.begin();
    const unsigned int n
      = cells.empty() ? 0 : cells[0]->get_fe().n_dofs_per_cell();
    for (const auto &color : plan.colors())
      parallel::apply_to_subranges(
        std::size_t(0),
        color.size(),
        [&](const std::size_t begin, const std::size_t end) {
          for (std::size_t c = begin; c < end; ++c)
            for (const std::size_t i : plan.plain_cells(color[c]))
              {
                const Vector<double> v        = cell_vector(i, n);
                const unsigned int  *position = plan.positions(i);
                for (unsigned int a = 0; a < n; ++a)
                  local[position[a]] += v(a);
              }
        },
        1);
    std::vector<types::global_dof_index> indices(n);
    for (const std::size_t i : plan.other_cells())
      {
        cells[i]->get_dof_indices(indices);
        constraints.distribute_local_to_global(cell_vector(i, n),
                                               indices,
                                               vector);
      }
    vector.compress(VectorOperation::add);
  }



  /// The plan made from the cells' positions in a local vector of the
  /// relevant entries (owned and ghost), the cells with a constrained entry
  /// left out (as the error estimator plans its cells): whether every cell
  /// is planned once, the plain cells with the positions given and the
  /// others exactly those with a constrained entry, and no position shared
  /// by two chunks of one color.
  bool
  plan_by_positions_right(const Cells                     &cells,
                          const IndexSet                  &relevant,
                          const AffineConstraints<double> &constraints)
  {
    const unsigned int n
      = cells.empty() ? 0 : cells[0]->get_fe().n_dofs_per_cell();
    std::vector<unsigned int>            positions(cells.size() * n);
    std::vector<bool>                    plain(cells.size(), true);
    std::vector<types::global_dof_index> indices(n);
    for (std::size_t i = 0; i < cells.size(); ++i)
      {
        cells[i]->get_dof_indices(indices);
        for (unsigned int a = 0; a < n; ++a)
          {
            positions[i * n + a] = relevant.index_within_set(indices[a]);
            plain[i] = plain[i] && !constraints.is_constrained(indices[a]);
          }
      }
    ConflictFreeChunks plan;
    plan.reinit(std::vector<unsigned int>(positions), n, plain, 8);
    std::vector<unsigned int> seen(cells.size(), 0);
    bool                      right = true;
    for (const auto &color : plan.colors())
      {
        std::set<unsigned int> of_color;
        for (const unsigned int c : color)
          {
            std::set<unsigned int> of_chunk;
            for (const std::size_t i : plan.plain_cells(c))
              {
                ++seen[i];
                right = right && plain[i];
                for (unsigned int a = 0; a < n; ++a)
                  {
                    right
                      = right && plan.positions(i)[a] == positions[i * n + a];
                    of_chunk.insert(plan.positions(i)[a]);
                  }
              }
            for (const unsigned int p : of_chunk)
              right = right && of_color.insert(p).second;
          }
      }
    for (const std::size_t i : plan.other_cells())
      {
        ++seen[i];
        right = right && !plain[i];
      }
    for (const unsigned int s : seen)
      right = right && (s == 1);
    return right;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 2);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);

  CornerRefinedMesh         mesh(comm, 4);
  const auto               &fe          = mesh.fe;
  const auto               &dof_handler = mesh.dof_handler;
  const IndexSet           &owned       = mesh.owned;
  const IndexSet           &relevant    = mesh.relevant;
  AffineConstraints<double> constraints(relevant);
  DoFTools::make_hanging_node_constraints(dof_handler, constraints);
  VectorTools::interpolate_boundary_values(dof_handler,
                                           0,
                                           Functions::ConstantFunction<2>(0.25,
                                                                          2),
                                           constraints);
  constraints.close();

  Cells cells;
  for (const auto &cell : dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
      cells.push_back(cell);
  const auto cell_indices = [&](const std::size_t i, auto &indices) {
    indices.resize(fe.n_dofs_per_cell());
    cells[i]->get_dof_indices(indices);
  };
  ConflictFreeChunks plan;
  const bool         outdated_before = plan.outdated(cells.size(), constraints);
  plan.reinit(cells.size(),
              cell_indices,
              *owned.begin(),
              owned.n_elements(),
              constraints,
              8);

  // Every cell once; plain cells clean; colors without a shared entry.
  std::vector<unsigned int>            seen(cells.size(), 0);
  bool                                 clean = true, conflict_free = true;
  std::vector<types::global_dof_index> indices;
  for (const auto &color : plan.colors())
    {
      std::set<unsigned int> positions_of_color;
      for (const unsigned int c : color)
        {
          std::set<unsigned int> positions_of_chunk;
          for (const std::size_t i : plan.plain_cells(c))
            {
              ++seen[i];
              cell_indices(i, indices);
              for (unsigned int a = 0; a < indices.size(); ++a)
                {
                  clean
                    = clean && owned.is_element(indices[a])
                      && !constraints.is_constrained(indices[a])
                      && plan.positions(i)[a] == indices[a] - *owned.begin();
                  positions_of_chunk.insert(plan.positions(i)[a]);
                }
            }
          for (const unsigned int p : positions_of_chunk)
            conflict_free
              = conflict_free && positions_of_color.insert(p).second;
        }
    }
  for (const std::size_t i : plan.other_cells())
    ++seen[i];
  bool once = true;
  for (const unsigned int s : seen)
    once = once && (s == 1);

  // Against the serial assembly of every cell, and 1 thread against 2.
  LA::MPI::Vector expected(owned, comm), by_plan(owned, comm),
    one_thread(owned, comm);
  for (std::size_t i = 0; i < cells.size(); ++i)
    {
      cell_indices(i, indices);
      constraints.distribute_local_to_global(cell_vector(i, indices.size()),
                                             indices,
                                             expected);
    }
  expected.compress(VectorOperation::add);
  assemble_by_plan(plan, cells, constraints, by_plan);
  MultithreadInfo::set_thread_limit(1);
  assemble_by_plan(plan, cells, constraints, one_thread);
  double difference = 0, same = 0;
  for (unsigned int k = 0; k < expected.locally_owned_size(); ++k)
    {
      difference = std::max(difference,
                            std::abs(expected.begin()[k] - by_plan.begin()[k]));
      same
        = std::max(same, std::abs(one_thread.begin()[k] - by_plan.begin()[k]));
    }
  difference = Utilities::MPI::max(difference, comm);
  same       = Utilities::MPI::max(same, comm);

  // A new constraint: the plan is outdated; the same set: it is not.
  const bool outdated_same = plan.outdated(cells.size(), constraints);
  AffineConstraints<double> more(relevant);
  more.copy_from(constraints);
  for (const auto i : owned)
    if (!more.is_constrained(i))
      {
        more.add_line(i);
        break;
      }
  const bool outdated_more = plan.outdated(cells.size(), more);

  const auto all
    = [&](const bool b) { return Utilities::MPI::min(b ? 1u : 0u, comm) == 1; };
  const auto yes = [](const bool b) { return b ? "yes" : "no"; };
  const bool several_colors
    = Utilities::MPI::max(static_cast<unsigned int>(plan.colors().size()), comm)
      > 1;
  // The reductions on every rank, the printing on rank 0.
  const bool all_once = all(once), all_clean = all(clean),
             all_conflict_free = all(conflict_free),
             all_before = all(outdated_before), any_same = !all(!outdated_same),
             any_more = !all(!outdated_more),
             all_by_positions
             = all(plan_by_positions_right(cells, relevant, constraints));
  if (rank == 0)
    {
      std::printf("every cell planned once: %s\n", yes(all_once));
      std::printf("plain cells: owned, unconstrained, positions right: %s\n",
                  yes(all_clean));
      std::printf("no entry shared within a color: %s\n",
                  yes(all_conflict_free));
      std::printf("more than one color: %s\n", yes(several_colors));
      std::printf("against distribute_local_to_global, below 1e-14: %s\n",
                  yes(difference < 1e-14));
      std::printf("1 thread and 2 threads, the same bits: %s\n",
                  yes(same == 0.));
      std::printf("outdated: before reinit %s, same constraints %s, one "
                  "more constraint %s\n",
                  yes(all_before),
                  yes(any_same),
                  yes(any_more));
      std::printf("planned by local positions (owned and ghost): every "
                  "cell once, no position shared within a color: %s\n",
                  yes(all_by_positions));
    }
}
