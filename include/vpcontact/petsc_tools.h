// The bridge from the program's Trilinos matrices and vectors to PETSc: a
// checked call macro and the copies of a matrix and of vector entries.
#ifndef vpcontact_petsc_tools_h
#define vpcontact_petsc_tools_h

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <petscmat.h>
#include <string>

// Every PETSc call returns an error code; a failed one stops the run with
// the call's text.
#define VPContactPetsc(call)                                   \
  do                                                           \
    {                                                          \
      const PetscErrorCode vpcontact_petsc_error = (call);     \
      AssertThrow(vpcontact_petsc_error == 0,                  \
                  dealii::ExcMessage(                          \
                    std::string("PETSc: ") + #call             \
                    + " failed with error code "               \
                    + std::to_string(vpcontact_petsc_error))); \
  } while (false)

namespace VPContact
{
  using namespace dealii;

  /**
   * The owned rows of a Trilinos matrix as a symmetric PETSc AIJ matrix with
   * the same rows on each rank (both take them in the order of the global
   * indices) and with the block size @p dofs_per_node, which GAMG
   * aggregates together. The caller destroys it.
   */
  Mat
  copy_to_petsc(const TrilinosWrappers::SparseMatrix &matrix,
                const unsigned int                    dofs_per_node);

  /// The owned entries of @p from into the PETSc vector @p to of the same
  /// layout.
  void
  copy_to_petsc(const TrilinosWrappers::MPI::Vector &from, Vec to);

  /// The owned entries of the PETSc vector @p from into @p to.
  void
  copy_from_petsc(Vec from, TrilinosWrappers::MPI::Vector &to);
} // namespace VPContact

#endif
