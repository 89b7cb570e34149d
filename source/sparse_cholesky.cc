// The CHOLMOD factorization of the displacement matrix on one process.
#include <vpcontact/sparse_cholesky.h>

#include <deal.II/base/exceptions.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <algorithm>
#include <array>
#include <dlfcn.h>
#include <future>
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



  // The substitutions are our own rather than cholmod_solve()'s. CHOLMOD
  // hands every supernode to the BLAS (dtrsv, dgemv), and OpenBLAS's dtrsv
  // takes a lock and a buffer from its memory pool on every call: on the
  // paper scene at 256^2 cells, a sixth of the time of a solve was spent
  // there. With one right-hand side each entry of L is used once, so a
  // solve is a stream through the factors and runs at the speed of the
  // memory if each entry costs few instructions: the loops take four
  // columns at a time, so that the entries they update or sum against are
  // loaded once per four columns.
  //
  // A supernode s holds the columns Super[s], ..., Super[s+1]-1 of L as
  // one dense block, by columns, whose first rows are these columns (the
  // diagonal block, lower triangular) and the rest the rows Ls[Lpi[s]+i]
  // below them.
  namespace
  {
    /// Four columns of a block, from the same row on.
    using FourColumns = std::array<const double *, 4>;

    /// t[i] -= sum_q c[q][i] y[q] for i < n, q < 4.
    inline void
    subtract_four_columns(const FourColumns &c,
                          const double       y[4],
                          double            *t,
                          const long         n)
    {
      for (long i = 0; i < n; ++i)
        t[i] -= (c[0][i] * y[0] + c[1][i] * y[1])
                + (c[2][i] * y[2] + c[3][i] * y[3]);
    }

    /// sum[q] += sum_i c[q][i] t[i] for i < n, q < 4.
    inline void
    add_four_dot_products(const FourColumns &c,
                          const double      *t,
                          const long         n,
                          double             sum[4])
    {
      double s0 = 0., s1 = 0., s2 = 0., s3 = 0.;
      for (long i = 0; i < n; ++i)
        {
          s0 += c[0][i] * t[i];
          s1 += c[1][i] * t[i];
          s2 += c[2][i] * t[i];
          s3 += c[3][i] * t[i];
        }
      sum[0] += s0;
      sum[1] += s1;
      sum[2] += s2;
      sum[3] += s3;
    }

    /// The block of supernode s of a factor: where its columns start in
    /// the unknowns, how many columns and rows it has, its entries and the
    /// rows below its diagonal block.
    struct Supernode
    {
      Supernode(const cholmod_factor &factor, const std::size_t s)
      {
        const long *super = static_cast<const long *>(factor.super);
        const long *pi    = static_cast<const long *>(factor.pi);
        const long *px    = static_cast<const long *>(factor.px);
        first             = super[s];
        n_cols            = super[s + 1] - first;
        n_rows            = pi[s + 1] - pi[s];
        n_below           = n_rows - n_cols;
        entries           = static_cast<const double *>(factor.x) + px[s];
        below = static_cast<const long *>(factor.s) + pi[s] + n_cols;
      }

      const double *
      column(const long j) const
      {
        return entries + j * n_rows;
      }

      /// Columns j, ..., j+3 from row @p row of the block on.
      FourColumns
      four_columns(const long j, const long row) const
      {
        return {{column(j) + row,
                 column(j + 1) + row,
                 column(j + 2) + row,
                 column(j + 3) + row}};
      }

      long          first, n_cols, n_rows, n_below;
      const double *entries;
      const long   *below;
    };
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
    // dissection only when AMD fills too much; on the paper scene it is
    // faster than METIS alone or nested dissection (scripts/bench).
    common.print = 0;
    // Supernodes also on small matrices, where CHOLMOD would otherwise
    // choose a simplicial L D L^T: the substitutions below are written for
    // the supernodal L L^T, and L L^T stops at the first pivot that is not
    // positive where L D L^T would go through an indefinite matrix without
    // complaint.
    common.supernodal = CHOLMOD_SUPERNODAL;
    // No explicit zeros in the supernodes beyond those of the smallest
    // ones (nrelax): CHOLMOD's default pads the supernodes with zeros so
    // that they are larger for the BLAS, which makes the factorization a
    // little faster and every solve read the padding: L is smaller and the
    // many solves faster without it, the one factorization a little slower.
    for (double &z : common.zrelax)
      z = 0.;
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

    // The split of the supernodes for the substitutions, and their
    // vectors, allocated here so that solve() allocates nothing.
    partition = SupernodePartition(*factor);
    permuted.resize(n);
    long most_below = 0;
    for (std::size_t s = 0; s < factor->nsuper; ++s)
      most_below = std::max(most_below, Supernode(*factor, s).n_below);
    for (unsigned int g = 0; g < 2; ++g)
      {
        below_values[g].resize(most_below);
        top_sums[g].resize(partition.top_columns.size());
      }
  }



  void
  SparseCholesky::solve(TrilinosWrappers::MPI::Vector       &dst,
                        const TrilinosWrappers::MPI::Vector &src,
                        const unsigned int                   n_threads) const
  {
    Assert(factor != nullptr, ExcMessage("factorize() first"));
    // K^{-1} = P^T L^{-T} L^{-1} P: row k of the permuted system is row
    // Perm[k] of K. On one process the local storage of the vectors is in
    // the global order, so they are read and written through it, without
    // an index lookup per entry.
    const long n = static_cast<long>(factor->n);
    Assert(static_cast<long>(src.locally_owned_size()) == n
             && static_cast<long>(dst.locally_owned_size()) == n,
           ExcMessage("The vectors must live on one process, as the factors"));
    const long   *perm   = static_cast<const long *>(factor->Perm);
    const double *source = src.begin();
    double       *target = dst.begin();
    for (long k = 0; k < n; ++k)
      permuted[k] = source[perm[k]];
    forward_substitution(n_threads);
    backward_substitution(n_threads);
    for (long k = 0; k < n; ++k)
      target[perm[k]] = permuted[k];
  }



  namespace
  {
    /// The forward substitution of supernode @p node: its unknowns of @p y
    /// solved for, and their products with the rows below subtracted, from
    /// the first @p n_direct rows in y, from the others (the rows of the
    /// top) in top_sum at their top_slot. @p e has room for the rows below.
    void
    forward_supernode(const Supernode &node,
                      double *const    y,
                      double *const    e,
                      const long       n_direct,
                      double *const    top_sum,
                      const int *const top_slot)
    {
      double *const x = y + node.first;
      // e collects minus the products of the rows below with x.
      std::fill(e, e + node.n_below, 0.);
      long j = 0;
      for (; j + 4 <= node.n_cols; j += 4)
        {
          const FourColumns c = node.four_columns(j, 0);
          // The 4 x 4 lower triangle on the diagonal.
          for (unsigned int q = 0; q < 4; ++q)
            {
              x[j + q] /= c[q][j + q];
              for (unsigned int p = q + 1; p < 4; ++p)
                x[j + p] -= c[q][j + p] * x[j + q];
            }
          subtract_four_columns(node.four_columns(j, j + 4),
                                x + j,
                                x + j + 4,
                                node.n_cols - j - 4);
          subtract_four_columns(node.four_columns(j, node.n_cols),
                                x + j,
                                e,
                                node.n_below);
        }
      for (; j < node.n_cols; ++j)
        {
          const double *const c = node.column(j);
          x[j] /= c[j];
          for (long i = j + 1; i < node.n_cols; ++i)
            x[i] -= c[i] * x[j];
          for (long i = 0; i < node.n_below; ++i)
            e[i] -= c[node.n_cols + i] * x[j];
        }
      for (long i = 0; i < n_direct; ++i)
        y[node.below[i]] += e[i];
      for (long i = n_direct; i < node.n_below; ++i)
        top_sum[top_slot[node.below[i]]] += e[i];
    }



    /// The backward substitution of supernode @p node: its unknowns of
    /// @p y solved for, given those of the rows below. @p e has room for
    /// the rows below.
    void
    backward_supernode(const Supernode &node, double *const y, double *const e)
    {
      double *const x = y + node.first;
      for (long i = 0; i < node.n_below; ++i)
        e[i] = y[node.below[i]];
      // The columns left over by the groups of four are the last ones, so
      // they come first here.
      const long n_grouped = node.n_cols - node.n_cols % 4;
      for (long j = node.n_cols; j-- > n_grouped;)
        {
          const double *const c   = node.column(j);
          double              sum = 0.;
          for (long i = j + 1; i < node.n_cols; ++i)
            sum += c[i] * x[i];
          for (long i = 0; i < node.n_below; ++i)
            sum += c[node.n_cols + i] * e[i];
          x[j] = (x[j] - sum) / c[j];
        }
      for (long j = n_grouped - 4; j >= 0; j -= 4)
        {
          const FourColumns c      = node.four_columns(j, 0);
          double            sum[4] = {0., 0., 0., 0.};
          add_four_dot_products(node.four_columns(j, j + 4),
                                x + j + 4,
                                node.n_cols - j - 4,
                                sum);
          add_four_dot_products(node.four_columns(j, node.n_cols),
                                e,
                                node.n_below,
                                sum);
          // The 4 x 4 upper triangle (the transposed diagonal block).
          for (unsigned int q = 4; q-- > 0;)
            {
              for (unsigned int p = q + 1; p < 4; ++p)
                sum[q] += c[q][j + p] * x[j + p];
              x[j + q] = (x[j + q] - sum[q]) / c[q][j + q];
            }
        }
    }



    /// work(0) and work(1), at once in two threads or one after the other.
    template <typename Work>
    void
    for_both_groups(const unsigned int n_threads, const Work &work)
    {
      if (n_threads >= 2)
        {
          // Should work(0) throw, the future's destructor waits for
          // work(1).
          std::future<void> other
            = std::async(std::launch::async, [&work]() { work(1); });
          work(0);
          other.get();
        }
      else
        {
          work(0);
          work(1);
        }
    }
  } // namespace



  // Forward: the two groups of subtrees (see SupernodePartition), each
  // adding what it subtracts from the rows of the top into its own sums;
  // then these sums, the first group's before the second's whatever the
  // threads, and the top. The same operations in the same order with one
  // thread or two, so the results are the same bits.
  void
  SparseCholesky::forward_substitution(const unsigned int n_threads) const
  {
    double *const y = permuted.data();
    for (auto &sums : top_sums)
      std::fill(sums.begin(), sums.end(), 0.);
    for_both_groups(n_threads, [&](const unsigned int g) {
      for (const auto &[first, last] : partition.groups[g])
        for (long s = first; s <= last; ++s)
          forward_supernode(Supernode(*factor, s),
                            y,
                            below_values[g].data(),
                            partition.rows_below_before_top[s],
                            top_sums[g].data(),
                            partition.top_slot.data());
    });
    for (std::size_t k = 0; k < partition.top_columns.size(); ++k)
      {
        y[partition.top_columns[k]] += top_sums[0][k];
        y[partition.top_columns[k]] += top_sums[1][k];
      }
    for (const long s : partition.top)
      forward_supernode(Supernode(*factor, s),
                        y,
                        below_values[0].data(),
                        partition.rows_below_before_top[s],
                        nullptr,
                        nullptr);
  }



  // Backward: the top first, then the two groups, which only read the
  // top's unknowns.
  void
  SparseCholesky::backward_substitution(const unsigned int n_threads) const
  {
    double *const y = permuted.data();
    for (auto t = partition.top.rbegin(); t != partition.top.rend(); ++t)
      backward_supernode(Supernode(*factor, *t), y, below_values[0].data());
    for_both_groups(n_threads, [&](const unsigned int g) {
      const auto &ranges = partition.groups[g];
      for (auto range = ranges.rbegin(); range != ranges.rend(); ++range)
        for (long s = range->second; s >= range->first; --s)
          backward_supernode(Supernode(*factor, s), y, below_values[g].data());
    });
  }



  double
  SparseCholesky::factor_nonzeros() const
  {
    return factor == nullptr ? 0. : common.lnz;
  }



  const SupernodePartition &
  SparseCholesky::supernode_partition() const
  {
    return partition;
  }
} // namespace VPContact
