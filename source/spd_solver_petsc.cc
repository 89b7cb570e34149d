// The PETSc implementation of SpdSolver: the matrix copied once into a PETSc
// AIJ matrix, PETSc's CG with GAMG or block Jacobi / ICC, or a Cholesky
// factorization by MUMPS or CHOLMOD through PETSc.
#include <vpcontact/spd_solver.h>

#include <deal.II/base/exceptions.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <algorithm>
#include <petscksp.h>
#include <string>
#include <utility>
#include <vector>

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
  namespace
  {
    class PetscSpdSolver : public SpdSolver
    {
    public:
      explicit PetscSpdSolver(const SpdMethod method)
        : method(method)
      {}

      ~PetscSpdSolver() override
      {
        release();
      }

      void
      initialize(const TrilinosWrappers::SparseMatrix &matrix,
                 const NearNullSpace                  &near_null_space) override
      {
        release();
        communicator = matrix.get_mpi_communicator();
        copy_matrix(matrix, near_null_space.dofs_per_node);
        VPContactPetsc(MatCreateVecs(A, &x, &b));
        VPContactPetsc(KSPCreate(communicator, &ksp));
        PC pc;
        VPContactPetsc(KSPGetPC(ksp, &pc));
        if (is_direct())
          {
            // Factorized once here, by KSPSetUp(); every solve reuses it.
            VPContactPetsc(KSPSetOperators(ksp, A, A));
            VPContactPetsc(KSPSetType(ksp, KSPPREONLY));
            VPContactPetsc(PCSetType(pc, PCCHOLESKY));
            VPContactPetsc(
              PCFactorSetMatSolverType(pc,
                                       method == SpdMethod::cholesky ?
                                         MATSOLVERCHOLMOD :
                                         MATSOLVERMUMPS));
          }
        else
          {
            make_inner_preconditioner(near_null_space);
            make_masked_operators();
            VPContactPetsc(KSPSetOperators(ksp, masked_matrix, A));
            VPContactPetsc(KSPSetType(ksp, KSPCG));
            VPContactPetsc(PCSetType(pc, PCSHELL));
            VPContactPetsc(PCShellSetContext(pc, this));
            VPContactPetsc(PCShellSetApply(pc, &apply_masked_preconditioner));
            // The test of deal.II's SolverControl: |b - A x| <= tolerance.
            VPContactPetsc(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
            VPContactPetsc(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE));
          }
        VPContactPetsc(KSPSetUp(ksp));
      }

      unsigned int
      solve(TrilinosWrappers::MPI::Vector       &solution,
            const TrilinosWrappers::MPI::Vector &rhs,
            SolverControl                       &control,
            const std::vector<unsigned int>     &held_rows) override
      {
        Assert(held_rows.empty() || !is_direct(), ExcNotImplemented());
        held = &held_rows;
        copy_to(rhs, b);
        copy_to(solution, x);
        if (!is_direct())
          VPContactPetsc(KSPSetTolerances(ksp,
                                          0.,
                                          control.tolerance(),
                                          PETSC_DEFAULT,
                                          control.max_steps()));
        VPContactPetsc(KSPSolve(ksp, b, x));
        held = &no_rows;
        KSPConvergedReason reason;
        VPContactPetsc(KSPGetConvergedReason(ksp, &reason));
        PetscInt iterations;
        VPContactPetsc(KSPGetIterationNumber(ksp, &iterations));
        if (reason < 0)
          {
            PetscReal residual;
            VPContactPetsc(KSPGetResidualNorm(ksp, &residual));
            throw SolverControl::NoConvergence(iterations, residual);
          }
        copy_from(x, solution);
        return is_direct() ? 1 : iterations;
      }

      void
      precondition(TrilinosWrappers::MPI::Vector       &dst,
                   const TrilinosWrappers::MPI::Vector &src) override
      {
        copy_to(src, b);
        if (is_direct())
          VPContactPetsc(KSPSolve(ksp, b, x));
        else
          VPContactPetsc(PCApply(inner, b, x));
        copy_from(x, dst);
      }

      bool
      is_direct() const override
      {
        return method != SpdMethod::cg_amg
               && method != SpdMethod::cg_incomplete_cholesky;
      }

    private:
      /**
       * The owned rows of the Trilinos matrix as a PETSc AIJ matrix with
       * the same rows on each rank (both take them in the order of the
       * global indices), and with the block size of the nodes, which GAMG
       * aggregates together.
       */
      void
      copy_matrix(const TrilinosWrappers::SparseMatrix &matrix,
                  const unsigned int                    dofs_per_node)
      {
        const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
        const int               n      = epetra.NumMyRows();
        std::vector<PetscInt>   row_start(n + 1, 0);
        std::vector<std::pair<PetscInt, PetscScalar>> row;
        std::vector<PetscInt>                         columns;
        std::vector<PetscScalar>                      values;
        columns.reserve(epetra.NumMyNonzeros());
        values.reserve(epetra.NumMyNonzeros());
        for (int r = 0; r < n; ++r)
          {
            int     length;
            double *entries;
            int    *local_columns;
            epetra.ExtractMyRowView(r, length, entries, local_columns);
            row.clear();
            for (int j = 0; j < length; ++j)
              row.emplace_back(epetra.ColMap().GID64(local_columns[j]),
                               entries[j]);
            std::sort(row.begin(), row.end(), [](const auto &p, const auto &q) {
              return p.first < q.first;
            });
            for (const auto &[column, value] : row)
              {
                columns.push_back(column);
                values.push_back(value);
              }
            row_start[r + 1] = columns.size();
          }
        VPContactPetsc(MatCreate(communicator, &A));
        VPContactPetsc(MatSetSizes(A, n, n, matrix.m(), matrix.n()));
        VPContactPetsc(MatSetBlockSize(A, dofs_per_node));
        VPContactPetsc(MatSetType(A, MATAIJ));
        VPContactPetsc(MatSeqAIJSetPreallocationCSR(A,
                                                    row_start.data(),
                                                    columns.data(),
                                                    values.data()));
        VPContactPetsc(MatMPIAIJSetPreallocationCSR(A,
                                                    row_start.data(),
                                                    columns.data(),
                                                    values.data()));
        VPContactPetsc(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
        VPContactPetsc(MatSetOption(A, MAT_SPD, PETSC_TRUE));
      }

      /**
       * GAMG with the near null space (orthonormalised, as PETSc requires),
       * or block Jacobi with an incomplete Cholesky factorization of each
       * rank's block. Options with the prefix "vpcontact_" given to PETSc
       * (PETSC_OPTIONS) reach it.
       */
      void
      make_inner_preconditioner(const NearNullSpace &near_null_space)
      {
        VPContactPetsc(PCCreate(communicator, &inner));
        VPContactPetsc(PCSetOperators(inner, A, A));
        VPContactPetsc(PCSetOptionsPrefix(inner, "vpcontact_"));
        if (method == SpdMethod::cg_amg)
          {
            VPContactPetsc(PCSetType(inner, PCGAMG));
            set_near_null_space(near_null_space);
          }
        else
          {
            VPContactPetsc(PCSetType(inner, PCBJACOBI));
            VPContactPetsc(
              PetscOptionsSetValue(nullptr, "-vpcontact_sub_pc_type", "icc"));
          }
        VPContactPetsc(PCSetFromOptions(inner));
        VPContactPetsc(PCSetUp(inner));
      }

      void
      set_near_null_space(const NearNullSpace &near_null_space)
      {
        const unsigned int n_modes = near_null_space.modes.size();
        if (n_modes == 0)
          return;
        std::vector<Vec> modes(n_modes);
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            VPContactPetsc(VecDuplicate(b, &modes[m]));
            copy_to(near_null_space.modes[m], modes[m]);
            // Gram-Schmidt against the modes before it.
            for (unsigned int l = 0; l < m; ++l)
              {
                PetscScalar dot;
                VPContactPetsc(VecDot(modes[m], modes[l], &dot));
                VPContactPetsc(VecAXPY(modes[m], -dot, modes[l]));
              }
            VPContactPetsc(VecNormalize(modes[m], nullptr));
          }
        MatNullSpace null_space;
        VPContactPetsc(MatNullSpaceCreate(communicator,
                                          PETSC_FALSE,
                                          n_modes,
                                          modes.data(),
                                          &null_space));
        VPContactPetsc(MatSetNearNullSpace(A, null_space));
        VPContactPetsc(MatNullSpaceDestroy(&null_space));
        for (Vec &v : modes)
          VPContactPetsc(VecDestroy(&v));
      }

      /// The matrix with its held rows masked (see SpdSolver).
      void
      make_masked_operators()
      {
        PetscInt n, N;
        VPContactPetsc(MatGetLocalSize(A, &n, nullptr));
        VPContactPetsc(MatGetSize(A, &N, nullptr));
        VPContactPetsc(
          MatCreateShell(communicator, n, n, N, N, this, &masked_matrix));
        VPContactPetsc(MatShellSetOperation(masked_matrix,
                                            MATOP_MULT,
                                            reinterpret_cast<void (*)(void)>(
                                              &apply_masked_matrix)));
      }

      static PetscErrorCode
      apply_masked_matrix(Mat shell, Vec in, Vec out)
      {
        PetscSpdSolver *self;
        PetscCall(MatShellGetContext(shell, &self));
        PetscCall(MatMult(self->A, in, out));
        return self->zero_held(out);
      }

      static PetscErrorCode
      apply_masked_preconditioner(PC shell, Vec in, Vec out)
      {
        PetscSpdSolver *self;
        PetscCall(PCShellGetContext(shell, &self));
        PetscCall(PCApply(self->inner, in, out));
        return self->zero_held(out);
      }

      PetscErrorCode
      zero_held(Vec v) const
      {
        if (held->empty())
          return 0;
        PetscScalar *entries;
        PetscCall(VecGetArray(v, &entries));
        for (const auto i : *held)
          entries[i] = 0.;
        PetscCall(VecRestoreArray(v, &entries));
        return 0;
      }

      static void
      copy_to(const TrilinosWrappers::MPI::Vector &from, Vec to)
      {
        PetscScalar *entries;
        VPContactPetsc(VecGetArray(to, &entries));
        std::copy(from.begin(), from.end(), entries);
        VPContactPetsc(VecRestoreArray(to, &entries));
      }

      static void
      copy_from(Vec from, TrilinosWrappers::MPI::Vector &to)
      {
        const PetscScalar *entries;
        VPContactPetsc(VecGetArrayRead(from, &entries));
        std::copy(entries, entries + to.locally_owned_size(), to.begin());
        VPContactPetsc(VecRestoreArrayRead(from, &entries));
      }

      void
      release()
      {
        if (ksp != nullptr)
          KSPDestroy(&ksp);
        if (inner != nullptr)
          PCDestroy(&inner);
        if (masked_matrix != nullptr)
          MatDestroy(&masked_matrix);
        if (A != nullptr)
          MatDestroy(&A);
        if (x != nullptr)
          VecDestroy(&x);
        if (b != nullptr)
          VecDestroy(&b);
      }

      const SpdMethod                  method;
      MPI_Comm                         communicator  = MPI_COMM_WORLD;
      Mat                              A             = nullptr;
      Mat                              masked_matrix = nullptr;
      PC                               inner         = nullptr;
      KSP                              ksp           = nullptr;
      Vec                              x = nullptr, b = nullptr;
      const std::vector<unsigned int>  no_rows;
      const std::vector<unsigned int> *held = &no_rows;
    };
  } // namespace



  std::unique_ptr<SpdSolver>
  create_petsc_spd_solver(const SpdMethod method)
  {
    return std::make_unique<PetscSpdSolver>(method);
  }
} // namespace VPContact
