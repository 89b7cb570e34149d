// CG for the damage problem on the free nodes, with (M)IC(0) of a region
// around them (see damage_region_solver.h).
#include <vpcontact/damage/damage_region_solver.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <cmath>

namespace VPContact
{
  void
  DamageRegionSolver::initialize(const OwnedRows     &rows_in,
                                 const Preconditioner kind_in)
  {
    rows          = &rows_in;
    halo          = rows->halo();
    communicator  = halo->get_mpi_communicator();
    kind          = kind_in;
    serial_layout = (Utilities::MPI::n_mpi_processes(communicator) == 1);
    n_owned       = rows->n_rows();
    const unsigned int n_ghosts = halo->n_ghost_indices();
    halo_owned.assign(n_owned, 0.);
    halo_send.assign(halo->n_import_indices(), 0.);
    ghost_values.assign(n_ghosts, 0.);

    is_free.assign(n_owned, false);
    free_nodes.clear();
    residual.assign(n_owned, 0.);
    preconditioned.assign(n_owned, 0.);
    product.assign(n_owned, 0.);
    direction.assign(n_owned + n_ghosts, 0.);
    region_valid = false;
    builds       = 0;
  }



  void
  DamageRegionSolver::begin_step()
  {
    region_valid = false;
  }



  unsigned int
  DamageRegionSolver::n_region_builds() const
  {
    return builds;
  }



  double
  DamageRegionSolver::target_of_last_solve() const
  {
    return last_target;
  }



  void
  DamageRegionSolver::build_region(const unsigned int rings)
  {
    const unsigned int *const row_start = rows->row_start().data();
    const unsigned int *const column    = rows->columns().data();
    // R: the free nodes, then ring after ring of their owned neighbours in
    // the matrix graph (ghost columns are left to their own rank).
    std::vector<bool>         in_region(is_free);
    std::vector<unsigned int> front(free_nodes);
    for (unsigned int ring = 0; ring < rings; ++ring)
      {
        std::vector<unsigned int> next;
        for (const unsigned int i : front)
          for (unsigned int e = row_start[i]; e < row_start[i + 1]; ++e)
            {
              const int j = owned_of_ghosted(column[e]);
              if (j >= 0 && !in_region[j])
                {
                  in_region[j] = true;
                  next.push_back(j);
                }
            }
        front.swap(next);
      }
    region.clear();
    region_index.assign(n_owned, -1);
    for (unsigned int i = 0; i < n_owned; ++i)
      if (in_region[i])
        {
          region_index[i] = region.size();
          region.push_back(i);
        }
    order_by_levels();
    factorize_region();
    region_valid = true;
    ++builds;
  }



  void
  DamageRegionSolver::order_by_levels()
  {
    const unsigned int *const row_start = rows->row_start().data();
    const unsigned int *const column    = rows->columns().data();
    // The triangular sweeps of the preconditioner are chains: in the
    // forward sweep node k waits for its neighbours before it, the last of
    // which was usually computed just before, so the processor runs one
    // row at a time, at the latency of its multiply-adds (about 20 cycles
    // per node for the two sweeps, measured at 512^2 cells). Level
    // scheduling: the level of a node is one more than the highest level
    // of its neighbours before it, so that the nodes of a level do not
    // depend on each other; numbered level by level, consecutive rows are
    // independent and the processor overlaps them. A neighbour before a
    // node has a lower level, so it stays before it: the lower triangle of
    // K_RR, and IC(0) on it, keep their entries, and only the order of the
    // sums within a row changes.
    const unsigned int        n = region.size();
    std::vector<unsigned int> level(n, 0);
    unsigned int              n_levels = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int i = region[k];
        for (unsigned int e = row_start[i]; e < row_start[i + 1]; ++e)
          {
            const int j = owned_of_ghosted(column[e]);
            if (j >= 0 && region_index[j] >= 0
                && static_cast<unsigned int>(region_index[j]) < k)
              level[k] = std::max(level[k], level[region_index[j]] + 1);
          }
        n_levels = std::max(n_levels, level[k] + 1);
      }
    // A stable counting sort by level.
    std::vector<unsigned int> level_start(n_levels + 1, 0);
    for (unsigned int k = 0; k < n; ++k)
      ++level_start[level[k] + 1];
    for (unsigned int l = 0; l < n_levels; ++l)
      level_start[l + 1] += level_start[l];
    std::vector<unsigned int> ordered(n);
    for (unsigned int k = 0; k < n; ++k)
      ordered[level_start[level[k]]++] = region[k];
    region.swap(ordered);
    for (unsigned int k = 0; k < n; ++k)
      region_index[region[k]] = k;
  }



  void
  DamageRegionSolver::factorize_region()
  {
    const unsigned int n = region.size();
    collect_lower_triangle();
    const std::vector<unsigned int> entry_in_rows = transpose_lower_triangle();

    if (kind == Preconditioner::diagonal)
      {
        // The sweeps use K's own entries: L^T by rows with K's values.
        upper_value.resize(factor_value.size());
        for (unsigned int c = 0; c < entry_in_rows.size(); ++c)
          upper_value[c] = factor_value[entry_in_rows[c]];
        prepare_diagonal_preconditioner();
        return;
      }
    factorize_by_columns(entry_in_rows);

    // Multiplications instead of divisions in the two sweeps, which run in
    // every CG iteration.
    inverse_diagonal.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      inverse_diagonal[k] = 1. / factor_diagonal[k];
    upper_value.resize(factor_value.size());
    for (unsigned int c = 0; c < entry_in_rows.size(); ++c)
      upper_value[c] = factor_value[entry_in_rows[c]];
    region_work.assign(n, 0.);
  }



  void
  DamageRegionSolver::collect_lower_triangle()
  {
    const unsigned int *const row_start = rows->row_start().data();
    const unsigned int *const column    = rows->columns().data();
    const double *const       value     = rows->values().data();
    // The lower triangle of K_RR in region indices, each row sorted; the
    // factorization overwrites it with L.
    const unsigned int n = region.size();
    factor_start.assign(1, 0);
    factor_column.clear();
    factor_value.clear();
    factor_diagonal.assign(n, 0.);
    std::vector<std::pair<unsigned int, double>> row;
    for (unsigned int k = 0; k < n; ++k)
      {
        const unsigned int i = region[k];
        row.clear();
        for (unsigned int e = row_start[i]; e < row_start[i + 1]; ++e)
          {
            const int j = owned_of_ghosted(column[e]);
            if (j < 0 || region_index[j] < 0)
              continue;
            const unsigned int r = region_index[j];
            if (r < k)
              row.emplace_back(r, value[e]);
            else if (r == k)
              factor_diagonal[k] = value[e];
          }
        std::sort(row.begin(), row.end());
        for (const auto &[r, a] : row)
          {
            factor_column.push_back(r);
            factor_value.push_back(a);
          }
        factor_start.push_back(factor_column.size());
      }
  }



  std::vector<unsigned int>
  DamageRegionSolver::transpose_lower_triangle()
  {
    const unsigned int n = region.size();
    // L^T by rows (the columns of L), with the position of each of its
    // entries in the rows of L. The factorization runs column by column
    // over it, and the backward sweep of the preconditioner gathers from
    // the rows after k as the forward sweep gathers from those before it.
    // (Scattered into the rows before k instead, each update waits for the
    // store of the previous one.)
    upper_start.assign(n + 1, 0);
    for (const unsigned int j : factor_column)
      ++upper_start[j + 1];
    for (unsigned int k = 0; k < n; ++k)
      upper_start[k + 1] += upper_start[k];
    upper_column.resize(factor_column.size());
    std::vector<unsigned int> entry_in_rows(factor_column.size());
    std::vector<unsigned int> next(upper_start.begin(), upper_start.end() - 1);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int e = factor_start[k]; e < factor_start[k + 1]; ++e)
        {
          const unsigned int j     = factor_column[e];
          upper_column[next[j]]    = k;
          entry_in_rows[next[j]++] = e;
        }
    return entry_in_rows;
  }



  void
  DamageRegionSolver::factorize_by_columns(
    const std::vector<unsigned int> &entry_in_rows)
  {
    // Right-looking incomplete Cholesky on the pattern of K_RR: column i
    // is scaled by its pivot, then updates the entries (k, j), i < j < k,
    // of the rows below it. IC(0) drops an update that falls outside the
    // pattern. MIC(0) (Gustafsson 1978) subtracts it from the diagonals of
    // both rows instead, so that L L^T has the row sums of K_RR: the error
    // of the preconditioner then vanishes on smooth vectors, the condition
    // number of the preconditioned Laplacian is O(1/h) instead of O(1/h^2)
    // and the iterations grow like h^{-1/2} instead of h^{-1}. For an
    // M-matrix with non-negative row sums, such as K_RR on the paper's
    // meshes (squares; M_L/k adds to the diagonal), the pivots of both stay
    // positive. Should one not, the diagonal of K is kept for it, which
    // still gives an SPD preconditioner.
    const double lumping
      = (kind == Preconditioner::modified_incomplete_cholesky ? 1. : 0.);
    const unsigned int  n = factor_diagonal.size();
    std::vector<double> diagonal_of_k(factor_diagonal);
    // MIC(0) starts, as the diagonal variant does, from a diagonal that
    // holds half of the cut rows' entries in other ranks' columns (see
    // cut_share_of_row_sums()).
    if (kind == Preconditioner::modified_incomplete_cholesky)
      {
        const std::vector<double> cut_share = cut_share_of_row_sums();
        for (unsigned int i = 0; i < n; ++i)
          factor_diagonal[i] += cut_share[i];
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        const double pivot = factor_diagonal[i];
        factor_diagonal[i] = std::sqrt(pivot > 0. ? pivot : diagonal_of_k[i]);
        const double       inverse = 1. / factor_diagonal[i];
        const unsigned int first = upper_start[i], last = upper_start[i + 1];
        for (unsigned int c = first; c < last; ++c)
          factor_value[entry_in_rows[c]] *= inverse;
        for (unsigned int c = first; c < last; ++c)
          {
            const unsigned int k    = upper_column[c];
            const double       l_ki = factor_value[entry_in_rows[c]];
            factor_diagonal[k] -= l_ki * l_ki;
            for (unsigned int d = first; d < c; ++d)
              {
                // (k, j): the entry of row k in column j, if any (rows are
                // sorted and hold a few entries).
                const unsigned int j = upper_column[d];
                const double update  = l_ki * factor_value[entry_in_rows[d]];
                unsigned int e       = factor_start[k];
                while (e < factor_start[k + 1] && factor_column[e] < j)
                  ++e;
                if (e < factor_start[k + 1] && factor_column[e] == j)
                  factor_value[e] -= update;
                else
                  {
                    factor_diagonal[k] -= lumping * update;
                    factor_diagonal[j] -= lumping * update;
                  }
              }
          }
      }
  }



  double
  DamageRegionSolver::vmult_free(std::vector<double> &dst,
                                 const double        *src,
                                 const double        *p)
  {
    const unsigned int *const row_start = rows->row_start().data();
    const unsigned int *const column    = rows->columns().data();
    const double *const       value     = rows->values().data();
    double                    p_dot_dst = 0;
    for (const unsigned int i : free_nodes)
      {
        double s = 0;
        for (unsigned int e = row_start[i]; e < row_start[i + 1]; ++e)
          s += value[e] * src[column[e]];
        dst[i] = s;
        p_dot_dst += p[i] * s;
      }
    return p_dot_dst;
  }



  double
  DamageRegionSolver::precondition_free(std::vector<double>       &dst,
                                        const std::vector<double> &src)
  {
    // y = (L L^T)^{-1} src on R (src vanishes on R \ F), then dst = y on F.
    std::vector<double> &y = region_work;
    const unsigned int   n = region.size();
    for (unsigned int k = 0; k < n; ++k)
      {
        double s = src[region[k]];
        for (unsigned int e = factor_start[k]; e < factor_start[k + 1]; ++e)
          s -= factor_value[e] * y[factor_column[e]];
        y[k] = s * inverse_diagonal[k];
      }
    for (unsigned int k = n; k-- > 0;)
      {
        double s = y[k];
        for (unsigned int e = upper_start[k]; e < upper_start[k + 1]; ++e)
          s -= upper_value[e] * y[upper_column[e]];
        y[k] = s * inverse_diagonal[k];
      }
    double src_dot_dst = 0;
    for (const unsigned int i : free_nodes)
      {
        dst[i] = y[region_index[i]];
        src_dot_dst += src[i] * dst[i];
      }
    return src_dot_dst;
  }



  double
  DamageRegionSolver::dot_free(const std::vector<double> &a,
                               const std::vector<double> &b) const
  {
    double s = 0;
    for (const unsigned int i : free_nodes)
      s += a[i] * b[i];
    return global_sum(s);
  }



  void
  DamageRegionSolver::take_free_nodes(const std::vector<unsigned int> &free)
  {
    // is_free marks the free set of the last solve: unmark it, mark the new
    // one, at the cost of the two sets rather than of the mesh.
    for (const unsigned int i : free_nodes)
      is_free[i] = false;
    free_nodes   = free;
    bool covered = region_valid;
    for (const unsigned int i : free_nodes)
      {
        is_free[i] = true;
        covered    = covered && region_index[i] >= 0;
      }
    if (!covered)
      build_region(2);
  }



  double
  DamageRegionSolver::start_product(const double *b, const double *x)
  {
    double *p = direction.data();
    for (const unsigned int i : free_nodes)
      p[i] = x[i];
    multiply_direction();
    double b_norm2 = 0;
    for (const unsigned int i : free_nodes)
      b_norm2 += b[i] * b[i];
    return global_sum(b_norm2);
  }



  double
  DamageRegionSolver::multiply_direction()
  {
    // The search direction vanishes off F; on several ranks the products
    // read its ghost entries too, sent by the ranks that own them.
    double *const p = direction.data();
    if (!serial_layout)
      {
        halo->export_to_ghosted_array_start<double>(
          0,
          make_array_view<const double>(p, p + n_owned),
          make_array_view(halo_send),
          make_array_view(p + n_owned, p + direction.size()),
          halo_requests);
        halo->export_to_ghosted_array_finish<double>(
          make_array_view(p + n_owned, p + direction.size()),
          halo_requests);
      }
    return global_sum(vmult_free(product, p, p));
  }



  double
  DamageRegionSolver::global_sum(const double local) const
  {
    return serial_layout ? local : Utilities::MPI::sum(local, communicator);
  }



  unsigned int
  DamageRegionSolver::solve(const LA::MPI::Vector           &b_vector,
                            LA::MPI::Vector                 &x_vector,
                            const std::vector<unsigned int> &held,
                            const double                     tolerance,
                            const unsigned int               max_iterations)
  {
    std::vector<bool> is_held(n_owned, false);
    for (const unsigned int i : held)
      is_held[i] = true;
    std::vector<unsigned int> free;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (!is_held[i])
        free.push_back(i);
    return solve_free(b_vector, x_vector, free, tolerance, max_iterations);
  }



  unsigned int
  DamageRegionSolver::solve_free(const LA::MPI::Vector           &b_vector,
                                 LA::MPI::Vector                 &x_vector,
                                 const std::vector<unsigned int> &free,
                                 const double                     tolerance,
                                 const unsigned int max_iterations)
  {
    return solve_free(b_vector.begin(),
                      x_vector.begin(),
                      free,
                      tolerance,
                      max_iterations);
  }



  unsigned int
  DamageRegionSolver::solve_free(const double                    *b,
                                 double                          *x,
                                 const std::vector<unsigned int> &free,
                                 const double                     tolerance,
                                 const unsigned int max_iterations)
  {
    take_free_nodes(free);
    if (kind == Preconditioner::diagonal)
      return solve_eisenstat(b, x, tolerance, max_iterations);
    double *p = direction.data();

    // r = b - K x with the start vector x (zero off F).
    const double b_norm2 = start_product(b, x);
    for (const unsigned int i : free_nodes)
      residual[i] = b[i] - product[i];
    if (b_norm2 == 0.)
      {
        // K_FF x_F = 0: x = 0, without iterations.
        for (const unsigned int i : free_nodes)
          x[i] = 0.;
        clean_up();
        return 0;
      }
    const double target = tolerance * std::sqrt(b_norm2);
    last_target         = target;

    // Preconditioned CG on F. NaN compares false: a non-finite residual
    // ends in NoConvergence, as too many iterations do. The dot products
    // are taken in the loops that compute their vectors (the preconditioner,
    // the product, the update), one pass over F fewer each: the damage
    // solves are limited by memory traffic.
    double       residual_norm = std::sqrt(dot_free(residual, residual));
    unsigned int iteration     = 0;
    double       rz            = 0;
    while (!(residual_norm <= target))
      {
        if (iteration == max_iterations || !std::isfinite(residual_norm))
          {
            clean_up();
            throw SolverControl::NoConvergence(iteration, residual_norm);
          }
        const double rz_next
          = global_sum(precondition_free(preconditioned, residual));
        const double beta = (iteration == 0 ? 0. : rz_next / rz);
        rz                = rz_next;
        for (const unsigned int i : free_nodes)
          p[i] = preconditioned[i] + beta * p[i];
        ++iteration;

        const double alpha = rz / multiply_direction();
        double       rr    = 0;
        for (const unsigned int i : free_nodes)
          {
            x[i] += alpha * p[i];
            residual[i] -= alpha * product[i];
            rr += residual[i] * residual[i];
          }
        residual_norm = std::sqrt(global_sum(rr));
      }
    clean_up();
    return iteration;
  }



  void
  DamageRegionSolver::clean_up()
  {
    // The work vectors must vanish off the next solve's free set: zero them
    // on this one.
    double *p = direction.data();
    for (const unsigned int i : free_nodes)
      p[i] = residual[i] = preconditioned[i] = product[i] = 0.;
  }
} // namespace VPContact
