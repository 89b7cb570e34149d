// ErrorEstimator: the section "Error estimate", and in every step the
// recovery of stress, strain and damage gradient on continuous Q1 fields and
// the space and time parts of the estimate (the work once per mesh is in
// error_estimator_setup.cc).
#include <vpcontact/input/input_error.h>
#include <vpcontact/refinement/error_estimator.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace VPContact
{
  namespace
  {
    template <int dim>
    constexpr unsigned int n_tensor
      = SymmetricTensor<2, dim>::n_independent_components;
    /// The number of recovered components: the stress and the strain, and
    /// with damage its gradient.
    template <int dim, bool damage>
    constexpr unsigned int n_fields = 2 * n_tensor<dim> + (damage ? dim : 0);
  } // namespace



  template <int dim>
  void
  ErrorEstimator<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Error estimate");
    prm.declare_entry(
      "Estimate error",
      "true",
      Patterns::Bool(),
      "Estimate the error of the run in the norm of the paper's Theorem 2 "
      "after every step: a space part (recovery of stress, strain and "
      "damage gradient) and a time part (the error of the forward Euler "
      "quadrature of the viscoplastic rate). It is printed at the end of "
      "the run, written to statistics.csv and convergence.csv, and drives "
      "adaptive cycles (doc/convergence.md).");
    prm.declare_entry(
      "Every steps",
      "1",
      Patterns::Integer(1),
      "Estimate at step 0, at every step whose number is a multiple of "
      "this, and at the last step of the run; the other steps leave the "
      "estimate columns of statistics.csv empty. The largest estimate over "
      "the steps and the cells' indicators are then taken over the "
      "estimated steps. The estimate grows with time in the scenes of "
      "doc/convergence.md, so its largest value is that of the last step, "
      "which every setting estimates; 10 (the steps written by Output/"
      "Output every, by default) makes the estimate about a tenth of its "
      "cost.");
    prm.leave_subsection();
  }



  template <int dim>
  void
  ErrorEstimator<dim>::parse_parameters(ParameterHandler &prm,
                                        const bool        for_adaptive_cycles)
  {
    prm.enter_subsection("Error estimate");
    active      = prm.get_bool("Estimate error");
    every_steps = prm.get_integer("Every steps");
    prm.leave_subsection();
    VPContactCheckParameter(active || !for_adaptive_cycles,
                            "Error estimate/Estimate error",
                            std::string("false"),
                            "adaptive cycles refine by the estimate's cell "
                            "indicators. Set it to true, or use Mesh "
                            "refinement/Strategy = uniform.");
  }



  template <int dim>
  bool
  ErrorEstimator<dim>::is_active() const
  {
    return active;
  }



  template <int dim>
  bool
  ErrorEstimator<dim>::estimates_step(const unsigned int n,
                                      const unsigned int n_steps) const
  {
    // Step 0 always: it stores the initial rate G_0 of the time part.
    return active && (n % every_steps == 0 || n == n_steps);
  }



  template <int dim>
  template <bool damage>
  void
  ErrorEstimator<dim>::evaluate_fields(const std::size_t        i,
                                       const double            *entries,
                                       SymmetricTensor<2, dim> *strain,
                                       Tensor<1, dim>          *gradient,
                                       double                  *zeta) const
  {
    // The strain, damage gradient and damage of the solution at the points
    // of cell i, from the cell's nodal values read once (the same sums, in
    // the same order, as CellKinematics::strains() and the others).
    const auto                 &cell = (*cells)[i];
    const Tensor<1, dim> *const grad = kinematics->shape_gradients(cell);
    std::array<std::array<double, max_nodes>, dim + 1> u;
    for (unsigned int d = 0; d < (damage ? dim + 1 : dim); ++d)
      kinematics->nodal_values(cell,
                               entries,
                               d,
                               make_array_view(&u[d][0], &u[d][0] + n_nodes));
    for (unsigned int q = 0; q < n_q; ++q)
      {
        Tensor<2, dim> du;
        Tensor<1, dim> g;
        double         z = 0;
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            const Tensor<1, dim> &G = grad[q * n_nodes + a];
            for (unsigned int d = 0; d < dim; ++d)
              du[d] += u[d][a] * G;
            if (damage)
              {
                g += u[dim][a] * G;
                z += u[dim][a] * kinematics->shape_value(q, a);
              }
          }
        strain[q]   = symmetrize(du);
        gradient[q] = g;
        zeta[q]     = (damage ? z : 1.);
      }
  }



  template <int dim>
  template <bool damage>
  void
  ErrorEstimator<dim>::point_values(const std::size_t        i,
                                    const double            *entries,
                                    double                  *f,
                                    SymmetricTensor<2, dim> *strain,
                                    double                  *zeta) const
  {
    // The fields the estimate recovers at the points of cell i, component
    // by component (f[q * n_c + c]): the stress of the history, the strain
    // and the damage gradient of the solution. Both passes compute them:
    // kept from one pass to the other they would take 16 doubles per point
    // of a 2D damage scene, more than the stress history and the largest
    // part of the estimate's memory, to save the second pass a gather of
    // the nodal values and a product with the shape gradients.
    constexpr unsigned int n_c    = n_fields<dim, damage>;
    const auto             points = history->get_data((*cells)[i]);
    std::array<Tensor<1, dim>, max_points> gradient;
    evaluate_fields<damage>(i, entries, strain, &gradient[0], zeta);
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int c = 0; c < n_tensor<dim>; ++c)
        {
          f[q * n_c + c]                 = points[q].stress.access_raw_entry(c);
          f[q * n_c + n_tensor<dim> + c] = strain[q].access_raw_entry(c);
          if (damage && c < dim)
            f[q * n_c + 2 * n_tensor<dim> + c] = gradient[q][c];
        }
  }



  template <int dim>
  template <bool damage>
  typename ErrorEstimator<dim>::CellNorms
  ErrorEstimator<dim>::first_pass(const std::size_t           i,
                                  const double               *entries,
                                  const ViscoplasticLaw<dim> &law,
                                  const bool                  initial,
                                  double                     *moments)
  {
    // On cell i: its moments int_K phi_a q_h for every node a and
    // component q of the recovered fields (into @p moments, component c of
    // node a at a * n_c + c), the squared norms of the solution, and the
    // squared norm of G_n - G_0, which needs nothing recovered (at n = 0,
    // G_0 is stored instead).
    constexpr unsigned int n_c    = n_fields<dim, damage>;
    const auto             points = history->get_data((*cells)[i]);
    const auto rates = std::as_const(*history).initial_rates((*cells)[i]);
    const ArrayView<SymmetricTensor<2, dim>> stored_rates
      = (initial ? history->initial_rates((*cells)[i]) :
                   ArrayView<SymmetricTensor<2, dim>>());
    const auto JxW = history->JxW((*cells)[i]);
    std::array<SymmetricTensor<2, dim>, max_points> strain;
    std::array<double, max_points>                  zeta;
    double                                          f[max_points * n_c];
    point_values<damage>(i, entries, f, &strain[0], &zeta[0]);
    std::fill(moments, moments + n_nodes * n_c, 0.);
    CellNorms size;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        size.solution_stress
          += scalar_product(points[q].stress, points[q].stress) * JxW[q];
        size.solution_strain += scalar_product(strain[q], strain[q]) * JxW[q];
        if (damage)
          size.solution_damage += zeta[q] * zeta[q] * JxW[q];
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            const double w = kinematics->shape_value(q, a) * JxW[q];
            for (unsigned int c = 0; c < n_c; ++c)
              moments[a * n_c + c] += w * f[q * n_c + c];
          }
        const auto rate = law.rate(points[q].stress, strain[q], zeta[q]);
        if (initial)
          stored_rates[q] = rate;
        const auto change = rate - rates[q];
        size.time += scalar_product(change, change) * JxW[q];
      }
    return size;
  }



  template <int dim>
  template <bool damage>
  void
  ErrorEstimator<dim>::add_plain_moments(const unsigned int          color,
                                         const double               *entries,
                                         const ViscoplasticLaw<dim> &law,
                                         const bool                  initial)
  {
    // The chunks of one color share no node: they run in any threads at
    // once, each adding its cells' moments to their nodes' entries of the
    // recovered fields (owned and ghost) in the cells' order, and summing
    // its cells' norms.
    constexpr unsigned int           n_c     = n_fields<dim, damage>;
    const std::vector<unsigned int> &colored = chunks.colors()[color];
    double *const                    values  = recovered.begin();
    parallel::apply_to_subranges(
      std::size_t(0),
      colored.size(),
      [&](const std::size_t begin, const std::size_t end) {
        double moments[max_nodes * n_c];
        for (std::size_t k = begin; k < end; ++k)
          {
            CellNorms &sums = chunk_norms[colored[k]];
            for (const std::size_t i : chunks.plain_cells(colored[k]))
              {
                sums += first_pass<damage>(i, entries, law, initial, moments);
                const unsigned int *const nodes = chunks.positions(i);
                for (unsigned int a = 0; a < n_nodes; ++a)
                  {
                    double *const node = values + std::size_t(nodes[a]) * n_c;
                    for (unsigned int c = 0; c < n_c; ++c)
                      node[c] += moments[a * n_c + c];
                  }
              }
          }
      },
      1);
  }



  template <int dim>
  void
  ErrorEstimator<dim>::add_constrained_moments(const std::size_t   i,
                                               const double *const moments)
  {
    // The moments of a (rare) cell with hanging nodes: a constrained
    // node's go to the nodes it hangs on, with the constraint's weights (as
    // AffineConstraints::distribute_local_to_global() would add them).
    double *const values      = recovered.begin();
    const auto   &partitioner = *lumped_mass.get_partitioner();
    for (unsigned int a = 0; a < n_nodes; ++a)
      {
        const double *const cell_moments = &moments[a * n_components];
        const auto          dof          = node_indices[i * n_nodes + a];
        if (!space.constraints->is_constrained(dof))
          {
            double *const node
              = values + chunks.positions(i)[a] * std::size_t(n_components);
            for (unsigned int c = 0; c < n_components; ++c)
              node[c] += cell_moments[c];
          }
        else
          for (const auto &entry :
               *space.constraints->get_constraint_entries(dof))
            {
              double *const node = values
                                   + partitioner.global_to_local(entry.first)
                                       * std::size_t(n_components);
              for (unsigned int c = 0; c < n_components; ++c)
                node[c] += entry.second * cell_moments[c];
            }
      }
  }



  template <int dim>
  void
  ErrorEstimator<dim>::project_to_nodes()
  {
    // sum_K int_K phi_i q_h for every component q of the recovered fields,
    // added by the first pass, in one exchange; divided by the lumped
    // mass; then the hanging nodes take their parents' average.
    const auto &partitioner = *lumped_mass.get_partitioner();
    recovered.compress(VectorOperation::add);
    double *const values = recovered.begin();
    for (unsigned int j = 0; j < partitioner.locally_owned_size(); ++j)
      if (lumped_mass.local_element(j) > 0)
        for (unsigned int c = 0; c < n_components; ++c)
          values[j * std::size_t(n_components) + c]
            /= lumped_mass.local_element(j);
    recovered.update_ghost_values();
    for (std::size_t h = 0; h < hanging_nodes.size(); ++h)
      for (unsigned int c = 0; c < n_components; ++c)
        {
          double value = 0;
          for (unsigned int p = hanging_start[h]; p < hanging_start[h + 1]; ++p)
            value
              += hanging_parents[p].second
                 * values[hanging_parents[p].first * std::size_t(n_components)
                          + c];
          values[hanging_nodes[h] * std::size_t(n_components) + c] = value;
        }
  }



  template <int dim>
  template <bool damage>
  typename ErrorEstimator<dim>::CellNorms
  ErrorEstimator<dim>::second_pass(const std::size_t i, const double *entries)
  {
    // On cell i: the squared distances between the recovered fields,
    // sum_a N_a(x_q) v_a, and the discrete ones, and the cell's indicator
    // (each cell writes only its own entries).
    constexpr unsigned int n_c = n_fields<dim, damage>;
    const auto             JxW = history->JxW((*cells)[i]);
    std::array<SymmetricTensor<2, dim>, max_points> point_strain;
    std::array<double, max_points>                  point_zeta;
    double                                          f[max_points * n_c];
    point_values<damage>(i, entries, f, &point_strain[0], &point_zeta[0]);
    const double *const       values = recovered.begin();
    const unsigned int *const nodes  = chunks.positions(i);
    double                    stress = 0, strain = 0, gradient = 0;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        double star[n_c] = {};
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            const double        N = kinematics->shape_value(q, a);
            const double *const v = values + std::size_t(nodes[a]) * n_c;
            for (unsigned int c = 0; c < n_c; ++c)
              star[c] += N * v[c];
          }
        // The differences as tensors, so that their norms are summed as
        // SymmetricTensor's scalar_product() sums them.
        SymmetricTensor<2, dim> stress_error, strain_error;
        Tensor<1, dim>          gradient_error;
        for (unsigned int c = 0; c < n_tensor<dim>; ++c)
          {
            stress_error.access_raw_entry(c) = star[c] - f[q * n_c + c];
            strain_error.access_raw_entry(c)
              = star[n_tensor<dim> + c] - f[q * n_c + n_tensor<dim> + c];
            if (damage && c < dim)
              gradient_error[c] = star[2 * n_tensor<dim> + c]
                                  - f[q * n_c + 2 * n_tensor<dim> + c];
          }
        stress += scalar_product(stress_error, stress_error) * JxW[q];
        strain += scalar_product(strain_error, strain_error) * JxW[q];
        gradient += gradient_error.norm_square() * JxW[q];
      }
    CellNorms norm;
    norm.stress     = stress;
    norm.strain     = strain;
    norm.damage     = gradient * damage_weights[i];
    const float eta = std::sqrt(norm.stress) + std::sqrt(norm.strain)
                      + std::sqrt(norm.damage);
    const unsigned int index = (*cells)[i]->active_cell_index();
    indicators[index]        = std::max(indicators[index], eta);
    step_indicators[index]   = eta;
    return norm;
  }



  template <int dim>
  template <bool damage>
  void
  ErrorEstimator<dim>::passes(const unsigned int          n,
                              const double               *entries,
                              const ViscoplasticLaw<dim> &law)
  {
    // Two passes over the cells in the threads, around the projection. The
    // first adds the cells' moments to the recovered fields (owned and
    // ghost entries, zeroed first): the cells without hanging nodes color
    // by color, then the others in this thread. Nothing per cell is kept
    // from one pass to the other. The second compares; both add each
    // cell's norms to its chunk's sums, in the cells' order.
    if (n == 0)
      history->keep_initial_rates();
    if (recovered.get_partitioner() != recovered_layout)
      recovered.reinit(recovered_layout);
    recovered = 0.;
    recovered.zero_out_ghost_values();
    chunk_norms.assign(chunks.n_chunks() + 1, CellNorms());
    for (unsigned int color = 0; color < chunks.colors().size(); ++color)
      add_plain_moments<damage>(color, entries, law, n == 0);
    double moments[max_nodes * n_fields<dim, damage>];
    for (const std::size_t i : chunks.other_cells())
      {
        chunk_norms.back()
          += first_pass<damage>(i, entries, law, n == 0, moments);
        add_constrained_moments(i, moments);
      }
    project_to_nodes();
    parallel::apply_to_subranges(
      0u,
      chunks.n_chunks(),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int c = begin; c < end; ++c)
          for (const std::size_t i : chunks.plain_cells(c))
            chunk_norms[c] += second_pass<damage>(i, entries);
      },
      1);
    for (const std::size_t i : chunks.other_cells())
      chunk_norms.back() += second_pass<damage>(i, entries);
  }



  template <int dim>
  ErrorEstimate
  ErrorEstimator<dim>::estimate_step(const unsigned int          n,
                                     const double                k,
                                     const double               *entries,
                                     const ViscoplasticLaw<dim> &law,
                                     const double                youngs_modulus)
  {
    // The number of recovered components is fixed at compile time in the
    // passes, so that their loops over the components are unrolled. A run
    // that estimates only some steps gives the recovered fields' memory
    // back before the step's fields are written (see recovered).
    if (with_damage)
      passes<true>(n, entries, law);
    else
      passes<false>(n, entries, law);
    if (every_steps > 1)
      dealii::LinearAlgebra::distributed::Vector<double>().swap(recovered);
    // G_0, stored by the estimate of step 0, is zero at every point for a
    // body at rest under the paper's law: its array then goes, and the
    // time part reads zeros (StressHistory).
    history->release_zero_initial_rates();
    return sum_norms(k, youngs_modulus);
  }



  template <int dim>
  ErrorEstimate
  ErrorEstimator<dim>::sum_norms(const double k, const double youngs_modulus)
  {
    // The chunks' sums added in the chunks' order (the same bits with any
    // number of threads), then over the ranks.
    double sums[7] = {0, 0, 0, 0, 0, 0, 0};
    for (const CellNorms &c : chunk_norms)
      {
        sums[0] += c.stress;
        sums[1] += c.strain;
        sums[2] += c.damage;
        sums[3] += c.time;
        sums[4] += c.solution_stress;
        sums[5] += c.solution_strain;
        sums[6] += c.solution_damage;
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 7),
                        triangulation->get_communicator(),
                        ArrayView<double>(sums, 7));
    ErrorEstimate estimate;
    estimate.space
      = std::sqrt(sums[0]) + std::sqrt(sums[1]) + std::sqrt(sums[2]);
    const double solution
      = std::sqrt(sums[4]) + std::sqrt(sums[5]) + std::sqrt(sums[6]);
    estimate.time = (1. + 1. / youngs_modulus) * 0.5 * k * std::sqrt(sums[3]);
    estimate.relative = solution > 0 ? estimate.sum() / solution : 0.;
    if (estimate.sum() > largest_sum.sum())
      largest_sum = estimate;
    largest_part.space    = std::max(largest_part.space, estimate.space);
    largest_part.time     = std::max(largest_part.time, estimate.time);
    largest_part.relative = std::max(largest_part.relative, estimate.relative);
    return estimate;
  }



  template <int dim>
  ErrorEstimate
  ErrorEstimator<dim>::largest() const
  {
    return largest_sum;
  }



  template <int dim>
  ErrorEstimate
  ErrorEstimator<dim>::largest_parts() const
  {
    return largest_part;
  }



  template <int dim>
  const Vector<float> &
  ErrorEstimator<dim>::cell_indicators() const
  {
    return indicators;
  }



  template <int dim>
  const Vector<float> &
  ErrorEstimator<dim>::last_step_indicators() const
  {
    return step_indicators;
  }



  template <int dim>
  std::map<std::string, double>
  ErrorEstimator<dim>::running_maxima() const
  {
    return {{"estimate_space", largest_sum.space},
            {"estimate_time", largest_sum.time},
            {"estimate_space_max", largest_part.space},
            {"estimate_time_max", largest_part.time},
            {"estimate_relative_max", largest_part.relative}};
  }



  template <int dim>
  void
  ErrorEstimator<dim>::restore_running_maxima(
    const std::map<std::string, double> &maxima)
  {
    const auto value = [&](const std::string &name) {
      const auto found = maxima.find(name);
      return found == maxima.end() ? 0. : found->second;
    };
    largest_sum  = {value("estimate_space"), value("estimate_time")};
    largest_part = {value("estimate_space_max"),
                    value("estimate_time_max"),
                    value("estimate_relative_max")};
  }



  template class ErrorEstimator<2>;
  template class ErrorEstimator<3>;
} // namespace VPContact
