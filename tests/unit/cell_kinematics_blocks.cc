// Unit test: CellKinematics stores one block of shape gradients for all the
// cells of a box also where deal.II runs several threads (its FEValues then
// computes every cell anew, and on a box whose cell size is no power of two
// the translates' gradients differ in the last bits), and every cell's
// gradients agree with FEValues' to round-off; on a distorted box every cell
// has its own block.
#include <vpcontact/fe/cell_kinematics.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <iostream>

using namespace VPContact;

// The blocks CellKinematics stores on @p mesh, and the largest difference of
// a cell's gradients from FEValues' relative to the largest gradient.
template <int dim>
void
check(const std::string &what, const Triangulation<dim> &mesh)
{
  const FESystem<dim> fe(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
  DoFHandler<dim>     dof_handler(mesh);
  dof_handler.distribute_dofs(fe);
  const QGauss<dim>   quadrature(2);
  LA::MPI::Vector     ghosted(dof_handler.locally_owned_dofs(), MPI_COMM_WORLD);
  CellKinematics<dim> kinematics;
  kinematics.reinit(dof_handler, quadrature, ghosted);

  const FE_Q<dim> scalar(1);
  FEValues<dim>   fe_values(scalar, quadrature, update_gradients);
  double          difference = 0, largest = 0;
  for (const auto &cell : dof_handler.active_cell_iterators())
    {
      fe_values.reinit(typename Triangulation<dim>::cell_iterator(cell));
      const Tensor<1, dim> *gradients = kinematics.shape_gradients(cell);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        for (unsigned int a = 0; a < kinematics.nodes_per_cell(); ++a)
          {
            const Tensor<1, dim> exact = fe_values.shape_grad(a, q);
            largest                    = std::max(largest, exact.norm());
            difference                 = std::max(
              difference,
              (gradients[q * kinematics.nodes_per_cell() + a] - exact).norm());
          }
    }
  std::cout << what << ": " << kinematics.n_gradient_blocks()
            << " block(s) of gradients for " << mesh.n_active_cells()
            << " cells; they agree with FEValues to 1e-12: "
            << (difference <= 1e-12 * largest ? "yes" : "no") << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 2);
  MultithreadInfo::set_thread_limit(2);
  std::cout << "deal.II runs more than one thread: "
            << (MultithreadInfo::n_threads() > 1 ? "yes" : "no") << std::endl;
  {
    Triangulation<3> box;
    GridGenerator::subdivided_hyper_rectangle(box,
                                              {7, 9, 11},
                                              Point<3>(0.1, 0, -0.3),
                                              Point<3>(1, 1.3, 0.7));
    check("3D box 7 x 9 x 11", box);
    GridTools::distort_random(0.2, box, true, 5);
    check("the same box distorted", box);
  }
  {
    Triangulation<2> box;
    GridGenerator::subdivided_hyper_rectangle(box,
                                              {30, 7},
                                              Point<2>(0, 0),
                                              Point<2>(1, 0.3));
    check("2D box 30 x 7", box);
  }
}
