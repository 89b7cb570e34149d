// The state of a run carried from one distributed mesh to the next when the
// mesh adapts during the run: nodal vectors and the quadrature point history.
#ifndef vpcontact_mesh_transfer_h
#define vpcontact_mesh_transfer_h

#include <vpcontact/fe/quadrature_field_transfer.h>
#include <vpcontact/fe/quadrature_history.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * One change of a parallel::distributed mesh with the data that lives on
   * it, in the manner of ASPECT's mesh refinement: the vectors go through
   * parallel::distributed::SolutionTransfer (interpolation of the Q1/P1
   * nodal fields onto the children; on coarsening, the children's values
   * at the parent's nodes), the stress history through deal.II's cell data
   * attachment with QuadratureFieldTransfer (the Gauss point polynomial
   * evaluated on the children; the L2 projection onto the parent). Both
   * travel with the cells when p4est partitions the new mesh.
   *
   * Use: the refinement flags set, prepare(), then the mesh's
   * execute_coarsening_and_refinement(), the setup of the new degrees of
   * freedom and of the history on the new cells, then unpack(). The object
   * must live from prepare() to unpack().
   */
  template <int dim>
  class MeshTransfer
  {
  public:
    MeshTransfer(parallel::distributed::Triangulation<dim> &triangulation,
                 const DoFHandler<dim>                     &dof_handler,
                 const Quadrature<dim>                     &quadrature);

    /// Attach the ghosted @p vectors and @p history (the old mesh's) to
    /// the cells. @p history must stay valid until the mesh has changed.
    void
    prepare(const std::vector<const LA::MPI::Vector *> &vectors,
            const StressHistory<dim>                   &history);

    /**
     * On the new mesh: fill the non-ghosted @p vectors (as many, in the
     * same order) and the @p history of every locally owned cell, which
     * must be initialized with the rule's points. Collective.
     */
    void
    unpack(const std::vector<LA::MPI::Vector *> &vectors,
           StressHistory<dim>                   &history);

  private:
    using cell_iterator = typename Triangulation<dim>::cell_iterator;

    /// The history of an active cell of the old mesh as doubles.
    std::vector<double>
    values_of(const StressHistory<dim> &history,
              const cell_iterator      &cell) const;

    /// Store @p values into the history of an active cell of the new mesh.
    void
    store(const std::vector<double> &values,
          StressHistory<dim>        &history,
          const cell_iterator       &cell) const;

    parallel::distributed::Triangulation<dim>                    &mesh;
    parallel::distributed::SolutionTransfer<dim, LA::MPI::Vector> solution;
    const QuadratureFieldTransfer<dim>                            fields;
    unsigned int                                                  handle = 0;
  };
} // namespace VPContact

#endif
