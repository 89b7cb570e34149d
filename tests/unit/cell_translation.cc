// Unit test: is_translate() finds the cells that are another cell moved
// without turning or deforming it (those whose elastic matrix the assembly
// reuses), and no other: the cells of subdivided boxes in 2D and 3D, a cell
// with one vertex moved by 1e-9 of its size, the children of a refined cell
// against a coarse one, triangles of either orientation, and two small
// cells far apart whose shapes differ by 1e-10 of their size, which deal.II's
// is_translation_of() (tolerance relative to their distance) takes for one.
#include <vpcontact/fe/cell_translation.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <iostream>
#include <string>
#include <vector>

using namespace VPContact;

/// The number of active cells of @p mesh that are translates of its first.
template <int dim>
unsigned int
translates_of_first(const Triangulation<dim> &mesh)
{
  const auto   first = mesh.begin_active();
  unsigned int count = 0;
  for (const auto &cell : mesh.active_cell_iterators())
    count += is_translate(cell, first) ? 1 : 0;
  return count;
}

template <int dim>
void
show(const std::string &what, const Triangulation<dim> &mesh)
{
  std::cout << what << ": " << translates_of_first(mesh) << " of "
            << mesh.n_active_cells() << " cells are translates of the first"
            << std::endl;
}

int
main()
{
  {
    Triangulation<2> box;
    GridGenerator::subdivided_hyper_rectangle(box,
                                              {8, 4},
                                              Point<2>(0, 0),
                                              Point<2>(2, 1));
    show("2D box 8 x 4", box);
    // One interior vertex moved by 1e-9 of the cell size: the four cells
    // around it are no translates any more.
    const double h = 0.25;
    for (const auto &cell : box.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if ((cell->vertex(v) - Point<2>(1., 0.5)).norm() < 1e-12)
          cell->vertex(v)[0] += 1e-9 * h;
    show("2D box 8 x 4, one vertex moved by 1e-9 h", box);
  }
  {
    Triangulation<3> box;
    GridGenerator::subdivided_hyper_rectangle(box,
                                              {3, 4, 5},
                                              Point<3>(-1, 0, 2),
                                              Point<3>(2, 1, 3));
    show("3D box 3 x 4 x 5", box);
    box.begin_active()->set_refine_flag();
    box.execute_coarsening_and_refinement();
    // The active cells of level 0 come first: the 59 coarse cells are
    // translates of each other, the 8 children of none of them.
    show("3D box with its first cell refined", box);
  }
  {
    Triangulation<2> triangles;
    GridGenerator::subdivided_hyper_rectangle_with_simplices(triangles,
                                                             {4, 4},
                                                             Point<2>(0, 0),
                                                             Point<2>(1, 1));
    show("2D box 4 x 4 of triangles", triangles);
  }
  {
    // Two cells of size 1e-3, 1e3 apart; the second's top right vertex is
    // off by 1e-13 (1e-10 of the size).
    const std::vector<Point<2>> vertices = {Point<2>(0, 0),
                                            Point<2>(1e-3, 0),
                                            Point<2>(0, 1e-3),
                                            Point<2>(1e-3, 1e-3),
                                            Point<2>(1e3, 0),
                                            Point<2>(1e3 + 1e-3, 0),
                                            Point<2>(1e3, 1e-3),
                                            Point<2>(1e3 + 1e-3 + 1e-13, 1e-3)};
    std::vector<CellData<2>>    cells(2);
    cells[0].vertices = {0, 1, 2, 3};
    cells[1].vertices = {4, 5, 6, 7};
    Triangulation<2> apart;
    apart.create_triangulation(vertices, cells, SubCellData());
    const auto first  = apart.begin_active();
    const auto second = std::next(first);
    std::cout << "small cells far apart, 1e-10 of their size different: "
              << "is_translate " << is_translate(second, first)
              << ", deal.II's is_translation_of "
              << second->is_translation_of(first) << std::endl;
  }
}
