// The fields of a checkpoint: the distributed mesh with the degree of freedom
// vectors and the quadrature point history attached to its cells.
#ifndef vpcontact_checkpoint_fields_h
#define vpcontact_checkpoint_fields_h

#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * Writing and reading the fields of a run with deal.II's serialization of
   * distributed meshes (as ASPECT's checkpoints do): p4est stores
   * the refinement of the coarse mesh, and every piece of data is attached
   * to the cells it belongs to, so that a checkpoint written on P ranks can
   * be read on Q ranks: each rank gets the data of the cells it owns after
   * the mesh is partitioned again.
   *
   * Two kinds of data travel with the cells, in this order:
   * - the degree of freedom vectors, through
   *   parallel::distributed::SolutionTransfer (the values of each cell's
   *   degrees of freedom; on the same mesh the transfer is an exact copy);
   * - the quadrature point history: QuadraturePointHistory::n_values doubles
   *   per point of every locally owned cell, a fixed size per cell.
   *
   * Reading is split in two because the data can only be unpacked once the
   * mesh is loaded and the caller has distributed the degrees of freedom and
   * created the (empty) history on the cells it now owns:
   * triangulation.load(filename), then the caller's setup, then
   * load_fields().
   */
  namespace CheckpointFields
  {
    /**
     * Attach the ghosted @p vectors and the history of the cells to the
     * mesh of @p dof_handler and write it all to @p filename (and the files
     * that deal.II and p4est derive from it: filename.info,
     * filename_fixed.data). Collective.
     */
    template <int dim>
    void
    save(parallel::distributed::Triangulation<dim>  &triangulation,
         const DoFHandler<dim>                      &dof_handler,
         const std::vector<const LA::MPI::Vector *> &vectors,
         const StressHistory<dim>                   &history,
         const unsigned int                          n_q_points,
         const std::string                          &filename);

    /**
     * After triangulation.load() and the setup of @p dof_handler: fill the
     * non-ghosted @p vectors (as many, in the same order as they were
     * saved) and the history of every locally owned cell, on which it must
     * already be initialized with @p n_q_points points. Collective.
     */
    template <int dim>
    void
    load(parallel::distributed::Triangulation<dim> &triangulation,
         const DoFHandler<dim>                     &dof_handler,
         const std::vector<LA::MPI::Vector *>      &vectors,
         StressHistory<dim>                        &history,
         const unsigned int                         n_q_points);

    /**
     * The sizes [bytes] of the files that save() meant to write under the
     * name @p name, for the files whose size follows from the mesh:
     * deal.II's file of the fixed-size cell records, NAME_fixed.data, with
     * @p bytes_per_cell bytes per cell (the vectors' values on the cell,
     * the stress history and deal.II's refinement status of the cell). The
     * manifest certifies a checkpoint only if the files on disk have these
     * sizes.
     */
    template <int dim>
    std::map<std::string, std::uintmax_t>
    expected_sizes(
      const parallel::distributed::Triangulation<dim> &triangulation,
      const std::string                               &name,
      const std::size_t                                bytes_per_cell);
  } // namespace CheckpointFields
} // namespace VPContact

#endif
