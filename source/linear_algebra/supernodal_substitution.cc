// SupernodalSubstitution: the two triangular substitutions with CHOLMOD's
// supernodal factor L L^T, one pass through the factor each.
#include <vpcontact/linear_algebra/supernodal_substitution.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cstring>

// The two passes are compiled for x86-64-v3 (AVX2 and FMA) besides the
// default target, and the loader picks the version the processor runs: the
// fused multiply-adds shorten the dependent chain of a dot product, and
// deal.II's own vectorisation is fixed when deal.II is compiled (generic
// for Debian's packages). The helpers they call are inlined into each
// version.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#  define VPCONTACT_SUBSTITUTION_TARGETS \
    __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#  define VPCONTACT_SUBSTITUTION_TARGETS
#endif
#if defined(__GNUC__)
#  define VPCONTACT_INLINE inline __attribute__((always_inline))
#else
#  define VPCONTACT_INLINE inline
#endif

namespace VPContact
{
  namespace
  {
    // Four doubles (GCC's and Clang's vector extension): one AVX register,
    // or two SSE2 registers on the default target.
    using Quad = double __attribute__((vector_size(4 * sizeof(double))));

    VPCONTACT_INLINE Quad
    load(const double *p)
    {
      Quad value;
      std::memcpy(&value, p, sizeof(Quad));
      return value;
    }

    VPCONTACT_INLINE void
    store(double *p, const Quad &value)
    {
      std::memcpy(p, &value, sizeof(Quad));
    }

    VPCONTACT_INLINE double
    sum_of(const Quad &q)
    {
      return (q[0] + q[1]) + (q[2] + q[3]);
    }

    /// The block of supernode s: its first unknown, its columns and rows,
    /// its entries by columns (the diagonal block first, lower triangular,
    /// then the rows below) and the unknowns of the rows below.
    struct Supernode
    {
      VPCONTACT_INLINE
      Supernode(const cholmod_factor &factor, const std::size_t s)
      {
        const auto *super = static_cast<const long *>(factor.super);
        const auto *pi    = static_cast<const long *>(factor.pi);
        const auto *px    = static_cast<const long *>(factor.px);
        first             = super[s];
        n_cols            = super[s + 1] - first;
        n_rows            = pi[s + 1] - pi[s];
        entries           = static_cast<const double *>(factor.x) + px[s];
        below = static_cast<const long *>(factor.s) + pi[s] + n_cols;
      }

      const double *
      column(const long j) const
      {
        return entries + j * n_rows;
      }

      long          first, n_cols, n_rows;
      const double *entries;
      const long   *below;
    };

    /// t[i] -= c[i] a for first <= i < end.
    VPCONTACT_INLINE void
    subtract_multiple(const double *const __restrict c,
                      const double a,
                      double *const __restrict t,
                      long       i,
                      const long end)
    {
      const Quad quad = {a, a, a, a};
      for (; i + 4 <= end; i += 4)
        store(t + i, load(t + i) - load(c + i) * quad);
      for (; i < end; ++i)
        t[i] -= c[i] * a;
    }

    /// sum_i c[i] t[i] for first <= i < end.
    VPCONTACT_INLINE double
    dot_product(const double *const __restrict c,
                const double *const __restrict t,
                long       i,
                const long end)
    {
      Quad sum = {0., 0., 0., 0.};
      for (; i + 4 <= end; i += 4)
        sum += load(c + i) * load(t + i);
      double result = sum_of(sum);
      for (; i < end; ++i)
        result += c[i] * t[i];
      return result;
    }

    /// sum[q] = sum_i c[q][i] t[i] for first <= i < end and q < 4: the
    /// four columns share the loads of t, and their four sums are
    /// independent chains.
    VPCONTACT_INLINE void
    four_dot_products(const double *const c[4],
                      const double *const __restrict t,
                      long       i,
                      const long end,
                      double     sum[4])
    {
      Quad s0 = {0., 0., 0., 0.}, s1 = s0, s2 = s0, s3 = s0;
      for (; i + 4 <= end; i += 4)
        {
          const Quad ti = load(t + i);
          s0 += load(c[0] + i) * ti;
          s1 += load(c[1] + i) * ti;
          s2 += load(c[2] + i) * ti;
          s3 += load(c[3] + i) * ti;
        }
      sum[0] = sum_of(s0);
      sum[1] = sum_of(s1);
      sum[2] = sum_of(s2);
      sum[3] = sum_of(s3);
      for (; i < end; ++i)
        for (unsigned int q = 0; q < 4; ++q)
          sum[q] += c[q][i] * t[i];
    }



    // L y = b, supernode by supernode. A supernode's unknowns and its rows
    // below are gathered into the block t, so that each column of L is one
    // contiguous update of t from its diagonal on, and every entry of L is
    // read once, in the order it is stored. Then the unknowns go back, and
    // what the columns subtract from the rows below is added to them.
    VPCONTACT_SUBSTITUTION_TARGETS void
    forward_pass(const cholmod_factor &factor,
                 const double *const   inverse_diagonal,
                 double *const         y,
                 double *const         t)
    {
      for (std::size_t s = 0; s < factor.nsuper; ++s)
        {
          const Supernode     node(factor, s);
          double *const       x       = y + node.first;
          const double *const inverse = inverse_diagonal + node.first;
          std::copy(x, x + node.n_cols, t);
          std::fill(t + node.n_cols, t + node.n_rows, 0.);
          for (long j = 0; j < node.n_cols; ++j)
            {
              t[j] *= inverse[j];
              subtract_multiple(node.column(j), t[j], t, j + 1, node.n_rows);
            }
          std::copy(t, t + node.n_cols, x);
          for (long i = node.n_cols; i < node.n_rows; ++i)
            y[node.below[i - node.n_cols]] += t[i];
        }
    }



    // L^T x = y, supernodes in reverse order. Unknown j of a supernode is
    // its entry minus the dot product of column j below the diagonal with
    // the block t of the later unknowns and the rows below (solved before).
    // Four columns at a time share the loads of t; the columns left over
    // by the groups of four are the last ones, so they come first.
    VPCONTACT_SUBSTITUTION_TARGETS void
    backward_pass(const cholmod_factor &factor,
                  const double *const   inverse_diagonal,
                  double *const         y,
                  double *const         t)
    {
      for (std::size_t s = factor.nsuper; s-- > 0;)
        {
          const Supernode     node(factor, s);
          double *const       x       = y + node.first;
          const double *const inverse = inverse_diagonal + node.first;
          std::copy(x, x + node.n_cols, t);
          for (long i = node.n_cols; i < node.n_rows; ++i)
            t[i] = y[node.below[i - node.n_cols]];
          const long n_grouped = node.n_cols - node.n_cols % 4;
          for (long j = node.n_cols; j-- > n_grouped;)
            t[j] = (t[j] - dot_product(node.column(j), t, j + 1, node.n_rows))
                   * inverse[j];
          for (long j = n_grouped - 4; j >= 0; j -= 4)
            {
              const double *const c[4] = {node.column(j),
                                          node.column(j + 1),
                                          node.column(j + 2),
                                          node.column(j + 3)};
              double              sum[4];
              four_dot_products(c, t, j + 4, node.n_rows, sum);
              // The 4 x 4 upper triangle (the transposed diagonal block).
              for (unsigned int q = 4; q-- > 0;)
                {
                  for (unsigned int p = q + 1; p < 4; ++p)
                    sum[q] += c[q][j + p] * t[j + p];
                  t[j + q] = (t[j + q] - sum[q]) * inverse[j + q];
                }
            }
          std::copy(t, t + node.n_cols, x);
        }
    }
  } // namespace



  void
  SupernodalSubstitution::initialize(const cholmod_factor &new_factor)
  {
    Assert(new_factor.is_super && new_factor.is_ll, ExcInternalError());
    factor = &new_factor;
    inverse_diagonal.resize(new_factor.n);
    long most_rows = 0;
    for (std::size_t s = 0; s < new_factor.nsuper; ++s)
      {
        const Supernode node(new_factor, s);
        for (long j = 0; j < node.n_cols; ++j)
          inverse_diagonal[node.first + j] = 1. / node.column(j)[j];
        most_rows = std::max(most_rows, node.n_rows);
      }
    permuted.resize(new_factor.n);
    block.resize(most_rows);
  }



  void
  SupernodalSubstitution::solve(const double *const source,
                                double *const       target) const
  {
    // K^{-1} = P^T L^{-T} L^{-1} P: row k of the permuted system is row
    // Perm[k] of K.
    Assert(factor != nullptr, ExcMessage("initialize() first"));
    const auto *perm = static_cast<const long *>(factor->Perm);
    const long  n    = static_cast<long>(factor->n);
    for (long k = 0; k < n; ++k)
      permuted[k] = source[perm[k]];
    forward_pass(*factor,
                 inverse_diagonal.data(),
                 permuted.data(),
                 block.data());
    backward_pass(*factor,
                  inverse_diagonal.data(),
                  permuted.data(),
                  block.data());
    for (long k = 0; k < n; ++k)
      target[perm[k]] = permuted[k];
  }
} // namespace VPContact
