// The bridge from the program's Trilinos matrices and vectors to PETSc: a
// checked call macro whose message says what PETSc said (and where
// PETSC_OPTIONS is set, that it may be the cause), the check of
// PETSC_OPTIONS before PETSc starts, and the copies of a matrix and of
// vector entries, and a PETSc operator whose products read the patterns of
// a matrix's rows.
#ifndef vpcontact_petsc_tools_h
#define vpcontact_petsc_tools_h

#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/row_pattern_matrix.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <petscmat.h>
#include <string>

// Every PETSc call returns an error code; a failed one stops the run with
// the call's text and PETSc's own words (petsc_failure_message()).
#define VPContactPetsc(call)                                                   \
  do                                                                           \
    {                                                                          \
      const PetscErrorCode vpcontact_petsc_error = (call);                     \
      AssertThrow(vpcontact_petsc_error == 0,                                  \
                  dealii::ExcMessage(                                          \
                    VPContact::petsc_failure_message(#call,                    \
                                                     vpcontact_petsc_error))); \
  } while (false)

namespace VPContact
{
  using namespace dealii;

  /**
   * What is wrong with the environment variable PETSC_OPTIONS that PETSc
   * cannot survive while it starts (an -options_file that cannot be read
   * makes PetscInitialize() abort the program), or an empty string. To be
   * asked before MPI and PETSc start.
   */
  std::string
  petsc_options_problem();

  /**
   * Replace PETSc's error handler, which prints some thirty lines of
   * traceback and configuration for every failed call, by one that keeps
   * the first line of the error for petsc_failure_message(). After PETSc
   * started.
   */
  void
  install_petsc_error_messages();

  /**
   * The message for the failed PETSc call @p call with @p code: PETSc's
   * own description and, if PETSC_OPTIONS is set, its value and what to do
   * about it (options prefixed vpcontact_ reach the program's solvers, so
   * an unknown type or an unreadable value there fails in them).
   */
  std::string
  petsc_failure_message(const std::string &call, const PetscErrorCode code);

  /**
   * The owned rows of a Trilinos matrix as a symmetric PETSc AIJ matrix with
   * the same rows on each rank (both take them in the order of the global
   * indices) and with the block size @p dofs_per_node, which GAMG
   * aggregates together. The caller destroys it.
   */
  Mat
  copy_to_petsc(const LA::SparseMatrix &matrix,
                const unsigned int      dofs_per_node);

  /**
   * A sequential PETSc AIJ matrix that reads the entries of @p matrix where
   * they are stored, without a copy, or nullptr where it cannot: on
   * several processes (PETSc splits each rank's rows into the columns it
   * owns and the others, Epetra keeps a row in one piece), or where
   * Epetra's local column indices are not the global ones in ascending
   * order within each row. A change of the matrix's values is then seen by
   * PETSc at once; MatAssemblyBegin/End() of the view tell its solvers.
   * @p matrix must keep its pattern and outlive the view; the caller
   * destroys it.
   */
  Mat
  view_in_petsc(const LA::SparseMatrix &matrix,
                const unsigned int      dofs_per_node);

  /// The owned entries of @p from into the PETSc vector @p to of the same
  /// layout.
  void
  copy_to_petsc(const LA::MPI::Vector &from, Vec to);

  /// The values of @p matrix into @p A, a copy_to_petsc() of it whose
  /// pattern it still has; PETSc's state of A marks the values as changed
  /// and its nonzero pattern as the same.
  void
  copy_values_to_petsc(const LA::SparseMatrix &matrix, Mat A);

  /// The owned entries of the PETSc vector @p from into @p to.
  void
  copy_from_petsc(Vec from, LA::MPI::Vector &to);

  /**
   * A PETSc operator (a shell matrix) with the products of @p patterns,
   * for the PETSc vectors of the layout copy_to_petsc() gives the matrix
   * the patterns were taken from: each rank's entries in the same order.
   * CG and the finest level of GAMG take their products from it, the same
   * as the matrix's to round-off, for a fraction of the memory traffic of
   * PETSc's AIJ product (see RowPatternMatrix). @p patterns must outlive
   * it; the caller destroys it.
   */
  Mat
  create_pattern_product(const RowPatternMatrix &patterns, MPI_Comm comm);
} // namespace VPContact

#endif
