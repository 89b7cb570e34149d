// The CHOLMOD factorization of the displacement matrix on one process.
#include <vpcontact/sparse_cholesky.h>

#include <deal.II/base/exceptions.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <algorithm>
#include <dlfcn.h>
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



  void
  set_blas_threads(const unsigned int n_threads)
  {
    // openblas_set_num_threads() is OpenBLAS's own, not part of the BLAS
    // interface, so it is looked up at run time and the program links
    // against any BLAS (Debian's alternatives choose it). Debian's OpenBLAS
    // comes as two files, libblas.so.3 and libopenblas.so.0, and the
    // libraries we link load both: each has its own thread count, and the
    // BLAS calls of CHOLMOD may go to either, so both are set.
    using Setter = void (*)(int);
    for (const char *library : {"libblas.so.3", "libopenblas.so.0"})
      if (void *handle = dlopen(library, RTLD_LAZY | RTLD_NOLOAD))
        {
          if (const auto setter = reinterpret_cast<Setter>(
                dlsym(handle, "openblas_set_num_threads")))
            setter(static_cast<int>(n_threads));
          dlclose(handle);
        }
  }



  SparseCholesky::SparseCholesky()
  {
    cholmod_l_start(&common);
    // CHOLMOD's default ordering strategy: AMD, and METIS or nested
    // dissection only when AMD fills too much. Measured on the paper scene
    // at 512^2 cells (789507 unknowns) with OpenBLAS: 4.9 s for the
    // analysis and the factorization, against 8.9 s with METIS alone and
    // 7.0 s with CHOLMOD's nested dissection.
    common.print = 0;
    // L L^T also on small matrices, where CHOLMOD would otherwise choose a
    // simplicial L D L^T, which goes through an indefinite matrix without
    // complaint; L L^T stops at the first pivot that is not positive.
    common.final_ll = 1;
  }



  SparseCholesky::~SparseCholesky()
  {
    release();
    cholmod_l_finish(&common);
  }



  void
  SparseCholesky::release()
  {
    for (cholmod_dense **d : {&rhs, &x, &workspace, &e_work})
      if (*d != nullptr)
        cholmod_l_free_dense(d, &common);
    if (factor != nullptr)
      cholmod_l_free_factor(&factor, &common);
  }



  void
  SparseCholesky::factorize(const TrilinosWrappers::SparseMatrix &matrix,
                            const unsigned int                    blas_threads)
  {
    // The supernodes of the factorization are dense products, large
    // enough at the sizes where it matters for two threads to pay: at
    // 512^2 cells (789507 unknowns) 4.7-5.1 s with one thread, 3.1 s with
    // two (three runs each, alternating). Nothing else runs at this point, so
    // the second core is free. The substitutions stay in one thread: they
    // run beside the damage step.
    set_blas_threads(blas_threads);
    try
      {
        factorize(matrix);
      }
    catch (...)
      {
        set_blas_threads(1);
        throw;
      }
    set_blas_threads(1);
  }



  void
  SparseCholesky::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    release();
    const Epetra_CrsMatrix &epetra = matrix.trilinos_matrix();
    const long              n      = epetra.NumMyRows();
    AssertThrow(static_cast<types::global_dof_index>(n) == matrix.m(),
                ExcMessage("The Cholesky factorization needs the whole "
                           "displacement matrix on one process; under "
                           "mpirun choose Solver/Linear solver = MUMPS or "
                           "CG with AMG."));

    cholmod_sparse *lower = lower_triangle(epetra, common);
    factor                = cholmod_l_analyze(lower, &common);
    if (factor != nullptr)
      cholmod_l_factorize(lower, factor, &common);
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

    rhs = cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &common);
    AssertThrow(rhs != nullptr,
                ExcMessage("CHOLMOD could not allocate a vector of size "
                           + std::to_string(n) + "."));
  }



  void
  SparseCholesky::solve(TrilinosWrappers::MPI::Vector       &dst,
                        const TrilinosWrappers::MPI::Vector &src) const
  {
    Assert(factor != nullptr, ExcMessage("factorize() first"));
    std::copy(src.begin(), src.end(), static_cast<double *>(rhs->x));
    const int ok = cholmod_l_solve2(CHOLMOD_A,
                                    factor,
                                    rhs,
                                    nullptr,
                                    &x,
                                    nullptr,
                                    &workspace,
                                    &e_work,
                                    &common);
    AssertThrow(ok == 1 && common.status == CHOLMOD_OK,
                ExcMessage("CHOLMOD could not solve with the factors (status "
                           + std::to_string(common.status) + ")."));
    const double *values = static_cast<const double *>(x->x);
    std::copy(values, values + x->nrow, dst.begin());
  }



  double
  SparseCholesky::factor_nonzeros() const
  {
    return factor == nullptr ? 0. : common.lnz;
  }
} // namespace VPContact
