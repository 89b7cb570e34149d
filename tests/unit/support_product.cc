// Unit test: SupportProduct::vmult() gives Trilinos' K x for a symmetric
// matrix on the pattern of a distributed Q1 mesh, for x nonzero at a few
// nodes (some of them next to another rank's nodes), at every node, and
// zero; y is overwritten, not added to. Serial and on 2 ranks.
#include <vpcontact/damage/support_product.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>

#include <iostream>

#include "q1_pattern_matrix.h"

using namespace VPContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  const Q1PatternMatrix   q1(comm);
  const IndexSet         &owned = q1.owned;
  const LA::SparseMatrix &K     = q1.K;

  OwnedRows rows;
  rows.reinit(K, owned, comm);
  SupportProduct product;
  product.initialize(rows);

  const unsigned int n = q1.dof_handler.n_dofs();
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
