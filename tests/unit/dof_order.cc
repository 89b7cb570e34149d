// Unit test: renumber_in_cell_order() numbers the degrees of freedom of a
// forest of one tree (cells on a Morton curve) as DoFRenumbering::
// component_wise() numbers those of the forest of one tree per cell (cells
// by rows), when the cells are taken by rows. A 16 x 16 box, Q1 vector and
// scalar fields in two blocks: on 1 rank every node and component has the
// same index on both meshes (and the Morton numbering does not); on 1 and 2
// ranks each rank keeps its owned indices, the new numbers are a
// permutation of them, each block keeps its indices, and within each block
// a rank's nodes come by rows.
#include <vpcontact/fe/dof_order.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <tuple>

using namespace VPContact;

namespace
{
  constexpr unsigned int n = 16;

  // Each locally owned index: (node's y, node's x, component).
  using Place = std::tuple<long, long, unsigned int>;
  std::map<types::global_dof_index, Place>
  places(const DoFHandler<2> &dof_handler)
  {
    std::map<types::global_dof_index, Place> result;
    const auto                              &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index>     indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            if (dof_handler.locally_owned_dofs().is_element(indices[i]))
              {
                // Q1: the index within the base element is the vertex.
                const Point<2> p
                  = cell->vertex(fe.system_to_component_index(i).second);
                result[indices[i]]
                  = Place(std::lround(p[1] * n),
                          std::lround(p[0] * n),
                          fe.system_to_component_index(i).first);
              }
        }
    return result;
  }

  void
  report(const std::string &what, const bool holds, const MPI_Comm comm)
  {
    const bool all = Utilities::MPI::min(holds ? 1 : 0, comm) == 1;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << what << ": " << (all ? "yes" : "no") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const FESystem<2>                fe(FE_Q<2>(1), 2, FE_Q<2>(1), 1);
  const std::vector<unsigned int>  blocks{0, 0, 1};

  // One tree per cell: the cells by rows.
  parallel::distributed::Triangulation<2> rows_mesh(comm);
  GridGenerator::subdivided_hyper_cube(rows_mesh, n);
  DoFHandler<2> by_rows(rows_mesh);
  by_rows.distribute_dofs(fe);
  DoFRenumbering::component_wise(by_rows, blocks);

  // One tree, refined: the cells on a Morton curve.
  parallel::distributed::Triangulation<2> forest(comm);
  GridGenerator::hyper_cube(forest);
  forest.refine_global(4);
  DoFHandler<2> morton(forest);
  morton.distribute_dofs(fe);
  DoFRenumbering::component_wise(morton, blocks);
  const IndexSet owned_before = morton.locally_owned_dofs();
  const auto     before       = places(morton);
  renumber_in_cell_order<2>(
    morton,
    blocks,
    [](const DoFHandler<2>::active_cell_iterator &cell) -> std::uint64_t {
      const Point<2> c = cell->center();
      return static_cast<std::uint64_t>(c[1] * n) * n
             + static_cast<std::uint64_t>(c[0] * n);
    });
  const auto after = places(morton);

  report("owned indices kept",
         morton.locally_owned_dofs() == owned_before,
         comm);
  // Every owned index holds a degree of freedom of the same block as
  // before, and every owned node and component has an index.
  bool blocks_kept = (after.size() == before.size());
  for (const auto &[index, place] : before)
    blocks_kept
      = blocks_kept && after.count(index) == 1
        && (std::get<2>(place) == 2) == (std::get<2>(after.at(index)) == 2);
  std::set<Place> distinct;
  for (const auto &entry : after)
    distinct.insert(entry.second);
  blocks_kept = blocks_kept && distinct.size() == after.size();
  report("a permutation within each block", blocks_kept, comm);
  bool by_row = true;
  for (auto it = after.begin(); std::next(it) != after.end(); ++it)
    {
      const auto &[y0, x0, c0] = it->second;
      const auto &[y1, x1, c1] = std::next(it)->second;
      // Within a block, after the first two rows (which the first row of
      // cells numbers together), a node's successor lies later in its row
      // or in a later row.
      if ((c0 == 2) == (c1 == 2) && y0 >= 2 && y1 >= 2)
        by_row = by_row && std::make_pair(y1, x1) >= std::make_pair(y0, x0);
    }
  report("a rank's nodes of a block by rows", by_row, comm);

  if (Utilities::MPI::n_mpi_processes(comm) == 1)
    {
      const auto reference = places(by_rows);
      std::cout << "Morton numbering equals the rows' numbering: "
                << (before == reference ? "yes" : "no") << std::endl;
      std::cout << "renumbered equals the rows' numbering: "
                << (after == reference ? "yes" : "no") << std::endl;
    }
}
