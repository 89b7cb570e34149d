// Unit test: SupportProduct::vmult() gives Trilinos' K x for a symmetric
// matrix on the pattern of a distributed Q1 mesh, for x nonzero at a few
// nodes (some of them next to another rank's nodes), at every node, and
// zero; y is overwritten, not added to. Serial and on 2 ranks.
#include <vpcontact/damage/support_product.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <iostream>

using namespace VPContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  parallel::distributed::Triangulation<2> triangulation(comm);
  GridGenerator::hyper_cube(triangulation);
  triangulation.refine_global(4);
  DoFHandler<2> dof_handler(triangulation);
  dof_handler.distribute_dofs(FE_Q<2>(1));
  const IndexSet owned = dof_handler.locally_owned_dofs();
  IndexSet       relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

  // K_ij = 1 + (i + j) % 7 on the pattern, 20 on the diagonal: symmetric.
  DynamicSparsityPattern pattern(relevant);
  DoFTools::make_sparsity_pattern(dof_handler, pattern);
  SparsityTools::distribute_sparsity_pattern(pattern, owned, comm, relevant);
  LA::SparseMatrix K;
  K.reinit(owned, owned, pattern, comm);
  for (const auto i : owned)
    for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
      {
        const auto j = entry->column();
        K.set(i, j, i == j ? 20. : 1. + (i + j) % 7);
      }
  K.compress(VectorOperation::insert);

  SupportProduct product;
  product.initialize(K, owned, comm);

  const unsigned int n = dof_handler.n_dofs();
  for (const unsigned int stride : {13u, 1u, 0u})
    {
      LA::MPI::Vector x(owned, comm), y(owned, comm), expected(owned, comm);
      for (const auto i : owned)
        x(i) = (stride > 0 && i % stride == 0 ? 1. + 0.01 * i : 0.);
      x.compress(VectorOperation::insert);
      y = 3.; // must be overwritten
      product.vmult(y, x);
      K.vmult(expected, x);
      y -= expected;
      const double error
        = y.linfty_norm() / std::max(1., expected.linfty_norm());
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        std::cout << "x nonzero at "
                  << (stride == 0 ? std::string("no node") :
                      stride == 1 ? std::string("every node") :
                                    "every " + std::to_string(stride) + "th of "
                                      + std::to_string(n) + " nodes")
                  << ": |y - K x| / |K x| below 1e-14: "
                  << (error < 1e-14 ? "yes" : "no") << std::endl;
    }
}
