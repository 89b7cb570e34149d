// The distributed vector, matrix and sparsity types of the program, named
// for their role, as step-40's LA namespace and ASPECT's global.h name them.
#ifndef vpcontact_linear_algebra_h
#define vpcontact_linear_algebra_h

#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * The types every field, matrix and sparsity pattern of a run lives in.
   * They are Trilinos' (Epetra) objects whichever package Solver/Linear
   * algebra chooses: the PETSc solvers (spd_solver_petsc.cc,
   * free_rows_system.cc) take these objects' rows and entries into their own
   * at the solve, so that assembly, the stress history, output and
   * checkpoints have one code path. Code that is specific to a package
   * (preconditioners, Epetra maps) names the package; all else names these.
   */
  namespace LA
  {
    namespace MPI
    {
      using Vector      = TrilinosWrappers::MPI::Vector;
      using BlockVector = TrilinosWrappers::MPI::BlockVector;
    } // namespace MPI
    using SparseMatrix    = TrilinosWrappers::SparseMatrix;
    using SparsityPattern = TrilinosWrappers::SparsityPattern;
  } // namespace LA
} // namespace VPContact

#endif
