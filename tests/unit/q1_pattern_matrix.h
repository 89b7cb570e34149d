// What the unit tests of SupportProduct and DamageWorkSet share: a symmetric
// Trilinos matrix on the pattern of a distributed Q1 mesh.
#ifndef vpcontact_tests_q1_pattern_matrix_h
#define vpcontact_tests_q1_pattern_matrix_h

#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

namespace VPContact
{
  /// The unit square refined 4 times with Q1 elements (289 nodes), and
  /// K_ij = 1 + (i + j) % 7 on its sparsity pattern, 20 on the diagonal.
  struct Q1PatternMatrix
  {
    explicit Q1PatternMatrix(const MPI_Comm comm)
      : triangulation(comm)
    {
      GridGenerator::hyper_cube(triangulation);
      triangulation.refine_global(4);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(FE_Q<2>(1));
      owned = dof_handler.locally_owned_dofs();
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      DynamicSparsityPattern pattern(relevant);
      DoFTools::make_sparsity_pattern(dof_handler, pattern);
      SparsityTools::distribute_sparsity_pattern(pattern,
                                                 owned,
                                                 comm,
                                                 relevant);
      K.reinit(owned, owned, pattern, comm);
      for (const auto i : owned)
        for (auto entry = pattern.begin(i); entry != pattern.end(i); ++entry)
          {
            const auto j = entry->column();
            K.set(i, j, i == j ? 20. : 1. + (i + j) % 7);
          }
      K.compress(VectorOperation::insert);
    }

    parallel::distributed::Triangulation<2> triangulation;
    DoFHandler<2>                           dof_handler;
    IndexSet                                owned;
    LA::SparseMatrix                        K;
  };
} // namespace VPContact

#endif
