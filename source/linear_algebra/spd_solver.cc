// The choice of a SpdSolver by package and method.
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/spd_solver.h>

#include <deal.II/base/mpi.h>

namespace VPContact
{
  std::unique_ptr<SpdSolver>
  create_trilinos_spd_solver(const SpdMethod method);
  std::unique_ptr<SpdSolver>
  create_petsc_spd_solver(const SpdMethod method);
  std::unique_ptr<SpdSolver>
  create_cholesky_spd_solver();



  std::string
  to_string(const LinearAlgebra package)
  {
    return package == LinearAlgebra::petsc ? "PETSc" : "Trilinos";
  }



  std::unique_ptr<SpdSolver>
  create_spd_solver(const LinearAlgebra package,
                    const SpdMethod     method,
                    const std::string  &entry)
  {
    // CHOLMOD factorizes on one process; under mpirun the matrix is split
    // over the ranks, and MUMPS is the distributed factorization.
    AssertThrow(method != SpdMethod::cholesky
                  || Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1,
                ExcMessage(entry
                           + " = Cholesky factorizes on one process only: run "
                             "without mpirun, or choose MUMPS (distributed) "
                             "or CG with AMG."));
    // CHOLMOD belongs to neither package: SparseCholesky serves both.
    if (method == SpdMethod::cholesky)
      return create_cholesky_spd_solver();
    return package == LinearAlgebra::petsc ? create_petsc_spd_solver(method) :
                                             create_trilinos_spd_solver(method);
  }
} // namespace VPContact
