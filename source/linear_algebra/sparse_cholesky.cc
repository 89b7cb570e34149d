// The CHOLMOD factorization of the displacement matrix on one process, and
// the solves with it.
#include <vpcontact/linear_algebra/blas_threads.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/sparse_cholesky.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  namespace
  {
    // The lower triangle of the symmetric matrix K by columns, as CHOLMOD
    // reads it (stype -1). Column j of the lower triangle is row j of the
    // upper triangle, so the rows of the Epetra matrix are read once, the
    // entries on and right of the diagonal kept. On one process local and
    // global column indices coincide. Epetra keeps the columns of a row in
    // the order of its column map; CHOLMOD wants them sorted.
    cholmod_sparse *
    lower_triangle(const Epetra_CrsMatrix &epetra, cholmod_common &common)
    {
      const long                           n = epetra.NumMyRows();
      std::vector<long>                    column_start(n + 1, 0);
      std::vector<std::pair<long, double>> entries;
      // Room for the upper triangle and the diagonal at once, and the
      // global index of every column looked up once: at 790k unknowns the
      // growing vector and a GCID() per entry took 0.7 s of the 7 s.
      entries.reserve((epetra.NumMyNonzeros() + n) / 2);
      const Epetra_Map &column_map = epetra.ColMap();
      std::vector<long> global_column(column_map.NumMyElements());
      for (std::size_t c = 0; c < global_column.size(); ++c)
        global_column[c] = column_map.GID64(c);
      for (long row = 0; row < n; ++row)
        {
          int     length;
          double *values;
          int    *columns;
          epetra.ExtractMyRowView(row, length, values, columns);
          const auto first = entries.size();
          for (int j = 0; j < length; ++j)
            {
              const long column = global_column[columns[j]];
              if (column >= row)
                entries.emplace_back(column, values[j]);
            }
          std::sort(entries.begin() + first, entries.end());
          column_start[row + 1] = entries.size();
        }

      cholmod_sparse *lower = cholmod_l_allocate_sparse(n,
                                                        n,
                                                        entries.size(),
                                                        1,
                                                        1,
                                                        -1,
                                                        CHOLMOD_REAL,
                                                        &common);
      AssertThrow(lower != nullptr,
                  ExcMessage("CHOLMOD could not allocate the matrix ("
                             + std::to_string(entries.size()) + " entries)."));
      std::copy(column_start.begin(),
                column_start.end(),
                static_cast<long *>(lower->p));
      auto *row_index = static_cast<long *>(lower->i);
      auto *entry     = static_cast<double *>(lower->x);
      for (std::size_t e = 0; e < entries.size(); ++e)
        {
          row_index[e] = entries[e].first;
          entry[e]     = entries[e].second;
        }
      return lower;
    }
  } // namespace



  SparseCholesky::SparseCholesky()
  {
    cholmod_l_start(&common);
    // CHOLMOD's default ordering strategy: AMD, and METIS or nested
    // dissection only when AMD fills too much; on the paper scene it is
    // faster than METIS alone or nested dissection (scripts/bench).
    common.print = 0;
    // Supernodes pay off where the factor's columns are long: CHOLMOD
    // chooses them when the flops per entry of L exceed the switch. Its
    // default of 40 picks supernodes for every mesh of this program; on the
    // small matrices of adapting runs (about 100 flops per entry) the
    // simplicial factorization is the faster one, the two are even near
    // 170 (the uniform 128^2 paper mesh), and supernodes are far ahead from
    // 300 on (256^2), measured with the factorizations of
    // prm/convergence/paper_fig1_adaptive_run.prm and of uniform meshes.
    common.supernodal        = CHOLMOD_AUTO;
    common.supernodal_switch = 120;
    // L L^T also for the simplicial factors, where CHOLMOD would otherwise
    // compute L D L^T: L L^T stops at the first pivot that is not positive
    // where L D L^T would go through an indefinite matrix without
    // complaint.
    common.final_ll = true;
  }



  SparseCholesky::~SparseCholesky()
  {
    release();
    cholmod_l_finish(&common);
  }



  void
  SparseCholesky::release()
  {
    if (factor != nullptr)
      cholmod_l_free_factor(&factor, &common);
    for (cholmod_dense **dense : {&solution, &workspace_y, &workspace_e})
      if (*dense != nullptr)
        cholmod_l_free_dense(dense, &common);
  }



  void
  SparseCholesky::factorize(const LA::SparseMatrix &matrix)
  {
    release();
    factorize_numerically(matrix, true);
  }



  void
  SparseCholesky::refactorize(const LA::SparseMatrix &matrix)
  {
    // A factorization that failed left no factor behind.
    if (factor == nullptr)
      {
        factorize(matrix);
        return;
      }
    Assert(static_cast<types::global_dof_index>(factor->n) == matrix.m(),
           ExcMessage("The pattern of the matrix changed: factorize() it"));
    factorize_numerically(matrix, false);
  }



  void
  SparseCholesky::factorize_numerically(const LA::SparseMatrix &matrix,
                                        const bool              analyze)
  {
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    const long              n      = epetra.NumMyRows();
    // create_spd_solver() refuses Cholesky under mpirun with the message
    // for the user; here the whole matrix is on this process.
    Assert(static_cast<types::global_dof_index>(n) == matrix.m(),
           ExcInternalError());

    cholmod_sparse *lower = lower_triangle(epetra, common);
    // cholmod_l_factorize() takes a symbolic factor or the numeric one of
    // the same pattern, whose order and supernodes it reuses.
    if (analyze)
      factor = cholmod_l_analyze(lower, &common);
    if (factor != nullptr)
      {
        // The supernodes' dense products, with deal.II's threads.
        const BlasThreads threads(MultithreadInfo::n_threads());
        cholmod_l_factorize(lower, factor, &common);
      }
    const int  status   = common.status;
    const bool definite = factor == nullptr || status == CHOLMOD_OUT_OF_MEMORY
                          || factor->minor == factor->n;
    const long pivot = (factor != nullptr ? factor->minor + 1 : 0);
    cholmod_l_free_sparse(&lower, &common);
    // Leave no half-made factor behind for solve() to use.
    if (!definite || status != CHOLMOD_OK)
      release();
    AssertThrow(definite,
                ExcMessage(
                  "The Cholesky factorization of the displacement matrix "
                  "broke down: the matrix is not positive definite (pivot "
                  + std::to_string(pivot) + " of " + std::to_string(n)
                  + " in the fill-reducing order is not positive). Check the "
                    "boundary conditions: a body that is not held has a "
                    "singular matrix."));
    AssertThrow(status == CHOLMOD_OK,
                ExcMessage("CHOLMOD could not factorize the displacement "
                           "matrix (status "
                           + std::to_string(status)
                           + "; -2 means out of memory). Use Solver/Linear "
                             "solver = CG with AMG, which needs far less "
                             "memory."));
  }



  bool
  SparseCholesky::is_supernodal() const
  {
    return factor != nullptr && factor->is_super;
  }



  void
  SparseCholesky::solve(LA::MPI::Vector &dst, const LA::MPI::Vector &src) const
  {
    Assert(factor != nullptr, ExcMessage("factorize() first"));
    const long n = static_cast<long>(factor->n);
    Assert(static_cast<long>(src.locally_owned_size()) == n
             && static_cast<long>(dst.locally_owned_size()) == n,
           ExcMessage("The vectors must live on one process, as the factors"));
    // cholmod_solve2() keeps its result and workspace between calls, so a
    // solve allocates nothing after the first; the right-hand side is
    // src's own storage (on one process the local storage of a vector is
    // in the global order).
    cholmod_dense rhs;
    rhs.nrow     = n;
    rhs.ncol     = 1;
    rhs.nzmax    = n;
    rhs.d        = n;
    rhs.x        = const_cast<double *>(src.begin());
    rhs.z        = nullptr;
    rhs.xtype    = CHOLMOD_REAL;
    rhs.dtype    = CHOLMOD_DOUBLE;
    const int ok = cholmod_l_solve2(CHOLMOD_A,
                                    factor,
                                    &rhs,
                                    nullptr,
                                    &solution,
                                    nullptr,
                                    &workspace_y,
                                    &workspace_e,
                                    &common);
    AssertThrow(ok != 0,
                ExcMessage("CHOLMOD could not solve with the factors of the "
                           "displacement matrix (status "
                           + std::to_string(common.status)
                           + "; -2 means out of memory)."));
    std::copy_n(static_cast<const double *>(solution->x), n, dst.begin());
  }
} // namespace VPContact
