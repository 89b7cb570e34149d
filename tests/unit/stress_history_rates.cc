// Unit test: the initial rates G_0 that StressHistory keeps beside its
// points read zero on a new mesh without an array of their own; written
// after keep_initial_rates(), they are given back by
// release_zero_initial_rates() only where every one of them is zero, and
// writing them without an array is refused.
#include <vpcontact/fe/quadrature_history.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <iostream>
#include <utility>

using namespace VPContact;

namespace
{
  // The largest |G_0| entry over the points, read through the const view.
  double
  largest_rate(const StressHistory<2> &history, const Triangulation<2> &mesh)
  {
    double largest = 0.;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto &rate : history.initial_rates(cell))
        largest = std::max(largest, rate.norm());
    return largest;
  }

  // Whether writing G_0 through the non-const view is accepted.
  bool
  writable(StressHistory<2> &history, const Triangulation<2> &mesh)
  {
    try
      {
        history.initial_rates(mesh.begin_active());
        return true;
      }
    catch (const ExceptionBase &)
      {
        return false;
      }
  }
} // namespace

int
main()
{
  deallog.depth_console(0);
  Triangulation<2> mesh;
  GridGenerator::hyper_cube(mesh);
  mesh.refine_global(2);
  StressHistory<2> history;
  for (const auto &cell : mesh.active_cell_iterators())
    history.initialize(cell, 4);
  std::cout << "new mesh: largest |G_0| " << largest_rate(history, mesh)
            << ", writable " << writable(history, mesh) << std::endl;

  history.keep_initial_rates();
  std::cout << "kept: writable " << writable(history, mesh) << std::endl;

  const Triangulation<2>::cell_iterator last = mesh.last_active();
  history.initial_rates(last)[3][0][1]       = 0.5;
  history.release_zero_initial_rates();
  std::cout << "one rate 0.5, released if zero: largest |G_0| "
            << largest_rate(history, mesh) << ", writable "
            << writable(history, mesh) << std::endl;

  history.initial_rates(last)[3][0][1] = 0.;
  history.release_zero_initial_rates();
  std::cout << "all zero, released if zero: largest |G_0| "
            << largest_rate(history, mesh) << ", writable "
            << writable(history, mesh) << std::endl;

  history.keep_initial_rates();
  std::cout << "kept again: largest |G_0| " << largest_rate(history, mesh)
            << ", writable " << writable(history, mesh) << std::endl;
}
