// Checks of a mesh before anything computes on it: the cells a mesh file
// holds, and whether the refined mesh can fit in the machines' memory.
#ifndef vpcontact_mesh_checks_h
#define vpcontact_mesh_checks_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>

#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * Throw a message starting with @p source (e.g. "Geometry/Mesh file =
   * l.msh") unless every cell of @p triangulation is a quadrilateral
   * (hexahedron in 3D) whose Jacobian determinant is positive at the
   * vertices and at the 2^dim Gauss points, relative to the cell's size.
   * In 2D a bilinear map whose Jacobian is positive at the four vertices is
   * positive everywhere, so this finds every inverted, degenerate or
   * self-intersecting ("bow-tie") quadrilateral; in 3D it finds all that
   * show at these points. The message names the cell by its vertices.
   */
  template <int dim>
  void
  check_mesh_cells(const Triangulation<dim> &triangulation,
                   const std::string        &source);

  /**
   * Throw a message naming @p entries (the parameters that set the mesh
   * size, with their values) if a mesh of @p n_active_cells cells, of which
   * every rank holds @p n_cells_on_every_rank (the coarse cells of p4est's
   * forest; with @p whole_mesh_on_every_rank, a shared mesh of simplices,
   * all cells), cannot fit in what the processes of this run may use: the
   * memory of each machine (or its cgroup limit) shared by its ranks, and
   * each rank's own limits (ulimit -v, ulimit -d). The estimate is a lower
   * bound, from the memory a cell of this program takes at least.
   * Collective.
   */
  void
  check_mesh_memory(const unsigned int dim,
                    const double       n_active_cells,
                    const double       n_cells_on_every_rank,
                    const bool         whole_mesh_on_every_rank,
                    const std::string &entries,
                    const MPI_Comm     communicator);
} // namespace VPContact

#endif
