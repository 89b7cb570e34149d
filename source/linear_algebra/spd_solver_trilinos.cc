// The Trilinos implementation of SpdSolver: deal.II's CG with ML or Ifpack
// preconditioners, and Amesos factorizations.
#include <vpcontact/input/input_error.h>
#include <vpcontact/linear_algebra/free_rows_system.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/row_pattern_matrix.h>
#include <vpcontact/linear_algebra/spd_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

namespace VPContact
{
  namespace
  {
    /**
     * x -> P A P x + (I - P) x for an operator A, P zeroing the held
     * entries. Every vector CG applies it to vanishes on the held entries
     * (b and the start vector do, and then the residuals, directions and
     * iterates, whose held entries only ever get sums of zeros), so P x = x
     * and the operator is A x with its held entries set to zero.
     */
    template <typename Apply>
    struct Masked
    {
      Apply                            apply;
      const std::vector<unsigned int> &held;

      void
      vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const
      {
        apply(dst, src);
        double *d = dst.begin();
        for (const auto i : held)
          d[i] = 0.;
      }
    };

    template <typename Apply>
    Masked<Apply>
    masked(const Apply &apply, const std::vector<unsigned int> &held)
    {
      return Masked<Apply>{apply, held};
    }



    class TrilinosSpdSolver : public SpdSolver
    {
    public:
      explicit TrilinosSpdSolver(const SpdMethod method)
        : method(method)
      {}

      void
      initialize(const LA::SparseMatrix &matrix,
                 const NearNullSpace    &near_null_space) override
      {
        this->matrix = &matrix;
        preconditioner.reset();
        row_patterns.reset();
        direct.reset();
        free_rows.clear();
        if (method == SpdMethod::cg_amg)
          initialize_amg(matrix, near_null_space);
        else if (method == SpdMethod::cg_incomplete_cholesky)
          {
            auto ic = std::make_unique<TrilinosWrappers::PreconditionIC>();
            ic->initialize(matrix);
            preconditioner = std::move(ic);
          }
        else
          {
            direct = std::make_unique<TrilinosWrappers::SolverDirect>(
              direct_control,
              TrilinosWrappers::SolverDirect::AdditionalData(
                false,
                method == SpdMethod::mumps ? "Amesos_Mumps" : "Amesos_Klu"));
            direct->initialize(matrix);
          }
      }

      unsigned int
      solve(LA::MPI::Vector                 &x,
            const LA::MPI::Vector           &b,
            SolverControl                   &control,
            const std::vector<unsigned int> &held) override
      {
        if (is_direct())
          {
            Assert(held.empty(), ExcNotImplemented());
            precondition(x, b);
            return 1;
          }
        // The branch is taken alike on all ranks (a rank may hold none of
        // its rows while another holds some): both call the same collective
        // operations today, but only a common decision keeps it so.
        SolverCG<LA::MPI::Vector> cg(control);
        if (!Utilities::MPI::logical_or(!held.empty(),
                                        matrix->get_mpi_communicator()))
          cg.solve(product(), x, b, *preconditioner);
        else if (method == SpdMethod::cg_incomplete_cholesky)
          solve_on_free_rows(x, b, cg, held);
        else
          cg.solve(masked([this](auto       &dst,
                                 const auto &src) { vmult(dst, src); },
                          held),
                   x,
                   b,
                   masked([this](auto       &dst,
                                 const auto &src) { precondition(dst, src); },
                          held));
        return control.last_step();
      }

      void
      precondition(LA::MPI::Vector &dst, const LA::MPI::Vector &src) override
      {
        if (preconditioner)
          preconditioner->vmult(dst, src);
        else
          direct->solve(dst, src);
      }

      void
      values_changed() override
      {
        if (row_patterns)
          row_patterns->update();
      }

      bool
      is_direct() const override
      {
        return method != SpdMethod::cg_amg
               && method != SpdMethod::cg_incomplete_cholesky;
      }

    private:
      /// y = K x, from the rows' patterns where the matrix has them.
      void
      vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const
      {
        if (row_patterns)
          row_patterns->vmult(dst, src);
        else
          matrix->vmult(dst, src);
      }

      /// K for deal.II's CG: vmult() above.
      struct Product
      {
        const TrilinosSpdSolver &solver;

        void
        vmult(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const
        {
          solver.vmult(dst, src);
        }
      };

      Product
      product() const
      {
        return Product{*this};
      }

      /**
       * CG on K_FF, the free rows' submatrix, preconditioned by IC(0) of
       * K_FF itself. Both are built again only when the free set changes;
       * the damage solves of a step change it at first and then confirm it.
       */
      void
      solve_on_free_rows(LA::MPI::Vector                 &x,
                         const LA::MPI::Vector           &b,
                         SolverCG<LA::MPI::Vector>       &cg,
                         const std::vector<unsigned int> &held)
      {
        if (free_rows.select(*matrix, held))
          {
            free_preconditioner.initialize(free_rows.matrix());
            free_rows.reinit_vector(x_free);
            free_rows.reinit_vector(b_free);
          }
        free_rows.restrict_to_free(x, x_free);
        free_rows.restrict_to_free(b, b_free);
        cg.solve(free_rows.matrix(), x_free, b_free, free_preconditioner);
        free_rows.extend_to_full(x_free, x);
      }

      /**
       * ML with the settings of step-42 for elasticity (few levels, a low
       * aggregation threshold) and, for a vector problem, the rigid motions
       * as its pre-computed null space: with the translations alone, the
       * coarse levels cannot represent a rotation, and CG needs more
       * iterations the finer the mesh.
       *
       * The smoother is a Chebyshev polynomial of the degree "smoother:
       * sweeps". In 2D, degree one: a cycle then costs two matrix products
       * fewer on the finest level, and CG needs more cycles, but fewer than
       * would make up for them where the products are limited by memory
       * traffic (meshes too large for the caches). In 3D, with rows of 81
       * entries instead of 18, degree one loses more cycles than it saves
       * products, and step-42's two sweeps stay (doc/design.md).
       */
      void
      initialize_amg(const LA::SparseMatrix &matrix,
                     const NearNullSpace    &near_null_space)
      {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        if (near_null_space.dofs_per_node > 1)
          {
            data.smoother_sweeps = (near_null_space.dofs_per_node == 2 ? 1 : 2);
            data.aggregation_threshold = 1e-2;
          }
        Teuchos::ParameterList              parameters;
        std::unique_ptr<Epetra_MultiVector> constant_modes;
        data.set_parameters(parameters,
                            constant_modes,
                            matrix.trilinos_matrix());
        // ML copies the modes into its own aggregation data when it builds
        // the hierarchy (ML_Aggregate_Set_NullSpace), so the contiguous
        // copy it reads them from goes once it is built: at 512^2 cells
        // in 2D, three vectors of the displacement block (12.6 MB).
        std::unique_ptr<Epetra_MultiVector> null_space;
        const unsigned int n_modes = near_null_space.modes.size();
        if (n_modes > 0)
          {
            null_space = std::make_unique<Epetra_MultiVector>(
              matrix.trilinos_matrix().RowMap(),
              n_modes);
            for (unsigned int m = 0; m < n_modes; ++m)
              std::copy(near_null_space.modes[m].begin(),
                        near_null_space.modes[m].end(),
                        (*null_space)[m]);
            parameters.set("PDE equations",
                           static_cast<int>(near_null_space.dofs_per_node));
            parameters.set("null space: type", "pre-computed");
            parameters.set("null space: dimension", static_cast<int>(n_modes));
            parameters.set("null space: vectors", null_space->Values());
          }
        // ML reads the matrix's rows to build its levels and takes the
        // finest level's products from the matrix it is given: from the
        // rows' patterns (RowPatternMatrix), the same bits for a fraction
        // of the memory traffic, where the rows repeat.
        auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        row_patterns
          = std::make_unique<RowPatternMatrix>(matrix.trilinos_matrix());
        if (row_patterns->compressed())
          amg->initialize(*row_patterns, parameters);
        else
          {
            row_patterns.reset();
            amg->initialize(matrix.trilinos_matrix(), parameters);
          }
        preconditioner = std::move(amg);
      }

      const SpdMethod         method;
      const LA::SparseMatrix *matrix = nullptr;
      /// The products of matrix from its rows' patterns; ML reads it, so
      /// it is declared before the preconditioner and outlives it.
      std::unique_ptr<RowPatternMatrix>                   row_patterns;
      std::unique_ptr<TrilinosWrappers::PreconditionBase> preconditioner;
      SolverControl                                       direct_control;
      std::unique_ptr<TrilinosWrappers::SolverDirect>     direct;
      FreeRowsSystem                                      free_rows;
      TrilinosWrappers::PreconditionIC                    free_preconditioner;
      LA::MPI::Vector                                     x_free, b_free;
    };
  } // namespace



  std::unique_ptr<SpdSolver>
  create_trilinos_spd_solver(const SpdMethod method)
  {
    return std::make_unique<TrilinosSpdSolver>(method);
  }
} // namespace VPContact
