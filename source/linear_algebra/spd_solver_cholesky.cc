// The SpdSolver of Solver/Linear solver = Cholesky: the supernodal
// factorization of SparseCholesky, for either linear algebra package.
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/sparse_cholesky.h>
#include <vpcontact/linear_algebra/spd_solver.h>

namespace VPContact
{
  namespace
  {
    /**
     * K factorized once in initialize(); every solve is one pair of
     * substitutions. The vectors are the program's Trilinos vectors
     * themselves, so neither package copies them.
     */
    class CholeskySpdSolver : public SpdSolver
    {
    public:
      void
      initialize(const LA::SparseMatrix &matrix, const NearNullSpace &) override
      {
        this->matrix = &matrix;
        factors.factorize(matrix);
      }

      unsigned int
      solve(LA::MPI::Vector       &x,
            const LA::MPI::Vector &b,
            SolverControl &,
            const std::vector<unsigned int> &held) override
      {
        (void)held;
        Assert(held.empty(), ExcNotImplemented());
        factors.solve(x, b);
        return 1;
      }

      void
      precondition(LA::MPI::Vector &dst, const LA::MPI::Vector &src) override
      {
        factors.solve(dst, src);
      }

      bool
      is_direct() const override
      {
        return true;
      }

      bool
      update_values() override
      {
        factors.refactorize(*matrix);
        return true;
      }

    private:
      const LA::SparseMatrix *matrix = nullptr;
      SparseCholesky          factors;
    };
  } // namespace



  std::unique_ptr<SpdSolver>
  create_cholesky_spd_solver()
  {
    return std::make_unique<CholeskySpdSolver>();
  }
} // namespace VPContact
