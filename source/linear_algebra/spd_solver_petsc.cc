// The PETSc implementation of SpdSolver: the matrix viewed (one process) or
// copied once into a PETSc AIJ matrix, PETSc's CG with GAMG or block Jacobi /
// ICC, or the Cholesky factorization of MUMPS through PETSc.
#include <vpcontact/linear_algebra/blas_threads.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/petsc_tools.h>
#include <vpcontact/linear_algebra/spd_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <memory>
#include <petscksp.h>
#include <string>
#include <vector>

namespace VPContact
{
  namespace
  {
    // PETSc stops CG as diverged once the residual exceeds 1e5 times the
    // right-hand side; a start vector from the last steps' increments may
    // begin there when the load barely changes, and CG still converges
    // from it (deal.II's SolverCG has no such test).
    constexpr PetscReal no_divergence_test = 1e300;

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
      initialize(const LA::SparseMatrix &matrix,
                 const NearNullSpace    &near_null_space) override
      {
        release();
        this->matrix = &matrix;
        communicator = matrix.get_mpi_communicator();
        // One process reads the entries where the program assembled them;
        // several take a copy in PETSc's layout.
        A             = view_in_petsc(matrix, near_null_space.dofs_per_node);
        values_shared = A != nullptr;
        if (!values_shared)
          A = copy_to_petsc(matrix, near_null_space.dofs_per_node);
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
            VPContactPetsc(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
          }
        else
          {
            set_near_null_space(near_null_space);
            set_cg_operators();
            configure_cg(ksp);
          }
        set_up();
      }

      unsigned int
      solve(LA::MPI::Vector                 &solution,
            const LA::MPI::Vector           &rhs,
            SolverControl                   &control,
            const std::vector<unsigned int> &held_rows) override
      {
        // Whether rows are held is decided over all ranks: the solve on the
        // free rows and the solve with all rows call different collective
        // PETSc functions, and a rank that holds none of its rows (its part
        // of the body all damaged, say) must still take the same branch as
        // one that holds some, or both wait for ever.
        const bool any_held
          = Utilities::MPI::logical_or(!held_rows.empty(), communicator);
        Assert(!any_held || !is_direct(), ExcNotImplemented());
        if (any_held)
          return solve_on_free_rows(solution, rhs, control, held_rows);
        copy_to_petsc(rhs, b);
        copy_to_petsc(solution, x);
        if (!is_direct())
          VPContactPetsc(KSPSetTolerances(ksp,
                                          0.,
                                          control.tolerance(),
                                          no_divergence_test,
                                          control.max_steps()));
        VPContactPetsc(KSPSolve(ksp, b, x));
        const unsigned int iterations = finished(ksp);
        copy_from_petsc(x, solution);
        return is_direct() ? 1 : iterations;
      }

      void
      precondition(LA::MPI::Vector &dst, const LA::MPI::Vector &src) override
      {
        copy_to_petsc(src, b);
        PC pc;
        VPContactPetsc(KSPGetPC(ksp, &pc));
        VPContactPetsc(PCApply(pc, b, x));
        copy_from_petsc(x, dst);
      }

      bool
      is_direct() const override
      {
        return method != SpdMethod::cg_amg
               && method != SpdMethod::cg_incomplete_cholesky;
      }

      bool
      update_values() override
      {
        // MUMPS: the same pattern, so PETSc's PCSetUp() reuses the
        // analysis (the ordering and the symbolic factorization) and
        // factorizes numerically only. The preconditioners of CG are built
        // anew.
        if (!is_direct() || A == nullptr)
          return false;
        release_free_rows();
        if (values_shared)
          {
            // The values are already there; an assembly marks them new.
            VPContactPetsc(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
            VPContactPetsc(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
          }
        else
          copy_values_to_petsc(*matrix, A);
        VPContactPetsc(KSPSetOperators(ksp, A, A));
        set_up();
        return true;
      }

    private:
      /// KSPSetUp(): the factorization or the preconditioner of A.
      void
      set_up()
      {
        // A factorization's dense products get deal.II's threads in the
        // BLAS; the solves keep one (see set_blas_threads()).
        const PetscErrorCode error = [this]() {
          const BlasThreads threads(is_direct() ? MultithreadInfo::n_threads() :
                                                  1);
          return KSPSetUp(ksp);
        }();
        AssertThrow(
          error == 0,
          ExcMessage(
            "PETSc could not build the "
            + std::string(is_direct() ? "factorization" : "preconditioner")
            + " of the matrix (PETSc error code " + std::to_string(error)
            + "): it is singular or not positive definite, or "
              "memory ran out. Check that the boundary conditions "
              "hold the body, or choose Solver/Linear solver = CG "
              "with AMG, which needs far less memory."));
        if (method == SpdMethod::cg_amg)
          release_product_data(ksp);
      }

      /**
       * GAMG forms each coarse level's operator as a Galerkin product
       * P^T A P and keeps in it what PETSc needs to form it again from new
       * values of A (MatPtAP with MAT_REUSE_MATRIX): the local and the
       * other ranks' rows of P, its transpose, the product's work arrays;
       * likewise the smoothed prolongators, products A P_0.
       * This program builds a new GAMG for new values (update_values()), so
       * that data only holds memory for the rest of the run;
       * MatProductClear() frees it.
       */
      static void
      release_product_data(KSP solver)
      {
        PC       pc;
        PetscInt n_levels;
        VPContactPetsc(KSPGetPC(solver, &pc));
        VPContactPetsc(PCMGGetLevels(pc, &n_levels));
        for (PetscInt level = 0; level + 1 < n_levels; ++level)
          {
            KSP smoother;
            Mat operator_matrix, preconditioning_matrix;
            VPContactPetsc(PCMGGetSmoother(pc, level, &smoother));
            VPContactPetsc(KSPGetOperators(smoother,
                                           &operator_matrix,
                                           &preconditioning_matrix));
            VPContactPetsc(MatProductClear(operator_matrix));
            if (preconditioning_matrix != operator_matrix)
              VPContactPetsc(MatProductClear(preconditioning_matrix));
            // The smoothed prolongator of the level above: a product A P_0.
            Mat interpolation;
            VPContactPetsc(PCMGGetInterpolation(pc, level + 1, &interpolation));
            VPContactPetsc(MatProductClear(interpolation));
          }
      }

      /**
       * K_FF x_F = b_F on the free rows alone: their submatrix
       * (MatCreateSubMatrix) with its own preconditioner, built again only
       * when the free set changes (see select_free_rows()). Where most rows
       * are held, as in the damage solves, whose free nodes are those near
       * the damaged zone, a solve costs in proportion to the free rows.
       */
      unsigned int
      solve_on_free_rows(LA::MPI::Vector                 &solution,
                         const LA::MPI::Vector           &rhs,
                         SolverControl                   &control,
                         const std::vector<unsigned int> &held_rows)
      {
        select_free_rows(held_rows);
        VPContactPetsc(KSPSetTolerances(free_ksp,
                                        0.,
                                        control.tolerance(),
                                        no_divergence_test,
                                        control.max_steps()));
        copy_to_petsc(rhs, b);
        copy_to_petsc(solution, x);
        Vec b_free, x_free;
        VPContactPetsc(VecGetSubVector(b, free_set, &b_free));
        VPContactPetsc(VecGetSubVector(x, free_set, &x_free));
        VPContactPetsc(KSPSolve(free_ksp, b_free, x_free));
        // Its GAMG is built by the first solve with a new free set.
        if (method == SpdMethod::cg_amg)
          release_product_data(free_ksp);
        VPContactPetsc(VecRestoreSubVector(b, free_set, &b_free));
        VPContactPetsc(VecRestoreSubVector(x, free_set, &x_free));
        const unsigned int iterations = finished(free_ksp);
        copy_from_petsc(x, solution);
        return iterations;
      }

      /**
       * The free rows' index set, submatrix and solver for @p held_rows,
       * kept from the last solve where no rank's free set changed (the
       * damage solves of a step end by confirming their sets, and the sets
       * of consecutive steps often agree).
       */
      void
      select_free_rows(const std::vector<unsigned int> &held_rows)
      {
        PetscInt first, last;
        VPContactPetsc(MatGetOwnershipRange(A, &first, &last));
        std::vector<bool> is_held(last - first, false);
        for (const auto i : held_rows)
          is_held[i] = true;
        std::vector<PetscInt> rows;
        for (PetscInt i = 0; i < last - first; ++i)
          if (!is_held[i])
            rows.push_back(first + i);
        if (!Utilities::MPI::logical_or(free_ksp == nullptr
                                          || rows != free_rows,
                                        communicator))
          return;
        release_free_rows();
        free_rows = std::move(rows);
        VPContactPetsc(ISCreateGeneral(communicator,
                                       free_rows.size(),
                                       free_rows.data(),
                                       PETSC_USE_POINTER,
                                       &free_set));
        VPContactPetsc(MatCreateSubMatrix(A,
                                          free_set,
                                          free_set,
                                          MAT_INITIAL_MATRIX,
                                          &free_matrix));
        VPContactPetsc(KSPCreate(communicator, &free_ksp));
        VPContactPetsc(KSPSetOperators(free_ksp, free_matrix, free_matrix));
        configure_cg(free_ksp);
      }

      void
      release_free_rows()
      {
        if (free_ksp != nullptr)
          KSPDestroy(&free_ksp);
        if (free_matrix != nullptr)
          MatDestroy(&free_matrix);
        if (free_set != nullptr)
          ISDestroy(&free_set);
      }

      /// The iterations of the last solve of @p solver; throws
      /// SolverControl::NoConvergence where it did not converge.
      static unsigned int
      finished(KSP solver)
      {
        KSPConvergedReason reason;
        VPContactPetsc(KSPGetConvergedReason(solver, &reason));
        PetscInt iterations;
        VPContactPetsc(KSPGetIterationNumber(solver, &iterations));
        if (reason < 0)
          {
            PetscReal residual;
            VPContactPetsc(KSPGetResidualNorm(solver, &residual));
            throw SolverControl::NoConvergence(iterations, residual);
          }
        return iterations;
      }

      /**
       * CG with GAMG or block Jacobi with ICC on each rank's block, stopped
       * as deal.II's SolverControl stops (|b - A x| <= its tolerance), from
       * the given start vector. Options prefixed "vpcontact_" in
       * PETSC_OPTIONS reach it.
       */
      void
      configure_cg(KSP solver) const
      {
        PC pc;
        VPContactPetsc(KSPSetType(solver, KSPCG));
        VPContactPetsc(KSPGetPC(solver, &pc));
        VPContactPetsc(
          PCSetType(pc, method == SpdMethod::cg_amg ? PCGAMG : PCBJACOBI));
        VPContactPetsc(
          PetscOptionsSetValue(nullptr, "-vpcontact_sub_pc_type", "icc"));
        VPContactPetsc(KSPSetOptionsPrefix(solver, "vpcontact_"));
        VPContactPetsc(KSPSetFromOptions(solver));
        VPContactPetsc(KSPSetNormType(solver, KSP_NORM_UNPRECONDITIONED));
        VPContactPetsc(KSPSetInitialGuessNonzero(solver, PETSC_TRUE));
      }

      /**
       * The operators of CG: its products, and with GAMG those of the
       * finest level (the smoother's and the residual's, PCSetUseAmat()),
       * from the patterns of the matrix's rows where they repeat, as with
       * Trilinos (RowPatternMatrix): PETSc's AIJ product reads 12 bytes
       * per entry and is most of a cycle's time on meshes too large for
       * the caches. GAMG builds its levels and its smoother's diagonal
       * from A, the preconditioning matrix.
       */
      void
      set_cg_operators()
      {
        row_patterns
          = std::make_unique<RowPatternMatrix>(matrix->trilinos_matrix());
        if (!row_patterns->compressed())
          {
            row_patterns.reset();
            VPContactPetsc(KSPSetOperators(ksp, A, A));
            return;
          }
        product = create_pattern_product(*row_patterns, communicator);
        VPContactPetsc(KSPSetOperators(ksp, product, A));
        if (method == SpdMethod::cg_amg)
          {
            PC pc;
            VPContactPetsc(KSPGetPC(ksp, &pc));
            VPContactPetsc(PCSetUseAmat(pc, PETSC_TRUE));
          }
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
            copy_to_petsc(near_null_space.modes[m], modes[m]);
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

      void
      release()
      {
        release_free_rows();
        if (ksp != nullptr)
          KSPDestroy(&ksp);
        if (product != nullptr)
          MatDestroy(&product);
        row_patterns.reset();
        if (A != nullptr)
          MatDestroy(&A);
        if (x != nullptr)
          VecDestroy(&x);
        if (b != nullptr)
          VecDestroy(&b);
      }

      const SpdMethod         method;
      const LA::SparseMatrix *matrix       = nullptr;
      MPI_Comm                communicator = MPI_COMM_WORLD;
      /// The matrix in PETSc: a view of the program's (view_in_petsc())
      /// where values_shared, else a copy.
      Mat  A             = nullptr;
      bool values_shared = false;
      /// CG's operator where the rows repeat: the products of row_patterns.
      std::unique_ptr<RowPatternMatrix> row_patterns;
      Mat                               product = nullptr;
      KSP                               ksp     = nullptr;
      Vec                               x = nullptr, b = nullptr;
      /// The free rows of the last solve that held rows, and their index
      /// set (pointing into free_rows), submatrix and solver.
      std::vector<PetscInt> free_rows;
      IS                    free_set    = nullptr;
      Mat                   free_matrix = nullptr;
      KSP                   free_ksp    = nullptr;
    };
  } // namespace



  std::unique_ptr<SpdSolver>
  create_petsc_spd_solver(const SpdMethod method)
  {
    return std::make_unique<PetscSpdSolver>(method);
  }
} // namespace VPContact
