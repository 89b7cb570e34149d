// ErrorEstimator: the section "Error estimate", the recovery of stress,
// strain and damage gradient on continuous Q1 fields, and the space and time
// parts of the estimate of every step.
#include <vpcontact/error_estimator.h>
#include <vpcontact/input_error.h>

#include <deal.II/base/parallel.h>
#include <deal.II/dofs/dof_tools.h>

#include <cmath>

namespace VPContact
{
  namespace
  {
    template <int dim>
    constexpr unsigned int n_tensor
      = SymmetricTensor<2, dim>::n_independent_components;
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
    prm.leave_subsection();
  }



  template <int dim>
  void
  ErrorEstimator<dim>::parse_parameters(ParameterHandler &prm,
                                        const bool        for_adaptive_cycles)
  {
    prm.enter_subsection("Error estimate");
    active = prm.get_bool("Estimate error");
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
  void
  ErrorEstimator<dim>::setup(const parallel::TriangulationBase<dim> &tria,
                             const std::vector<cell_iterator> &owned_cells,
                             const CellKinematics<dim>        &cell_kinematics,
                             StressHistory<dim>               &stress_history)
  {
    // A scalar Q1 (P1) space on the mesh; its owned and ghost nodes hold the
    // recovered fields, one block per component.
    triangulation = &tria;
    cells         = &owned_cells;
    kinematics    = &cell_kinematics;
    history       = &stress_history;
    with_damage   = cell_kinematics.has_damage();
    recovery_fe   = cell_kinematics.scalar_element().clone();
    recovery_dofs.reinit(tria);
    recovery_dofs.distribute_dofs(*recovery_fe);
    const IndexSet owned = recovery_dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(recovery_dofs, relevant);
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(recovery_dofs, constraints);
    constraints.close();

    const MPI_Comm communicator = tria.get_communicator();
    lumped_mass.reinit(owned, relevant, communicator);
    recovered.reinit(2 * n_tensor<dim> + (with_damage ? dim : 0));
    for (unsigned int b = 0; b < recovered.n_blocks(); ++b)
      recovered.block(b).reinit(owned, relevant, communicator);
    recovered.collect_sizes();

    AssertThrow(owned_cells.empty()
                  || stress_history.JxW(owned_cells[0]).size()
                       <= PointValues::max_points,
                ExcMessage("ErrorEstimator: more quadrature points per cell "
                           "than it is built for."));
    setup_nodes_and_mass();
    indicators.reinit(tria.n_active_cells());
    largest_sum  = ErrorEstimate();
    largest_part = ErrorEstimate();
  }



  template <int dim>
  void
  ErrorEstimator<dim>::setup_nodes_and_mass()
  {
    // The nodes of every owned cell, by global index, and the lumped mass
    // sum_K int_K phi_i (condensed onto the nodes that carry the values
    // where the mesh has hanging nodes).
    const unsigned int n_nodes = recovery_fe->n_dofs_per_cell();
    node_indices.resize((*cells).size() * n_nodes);
    node_locals.resize((*cells).size() * n_nodes);
    has_constraints.assign((*cells).size(), false);
    std::vector<types::global_dof_index> dofs(n_nodes);
    Vector<double>                       cell_mass(n_nodes);
    for (std::size_t i = 0; i < (*cells).size(); ++i)
      {
        const typename DoFHandler<dim>::active_cell_iterator cell(
          triangulation,
          (*cells)[i]->level(),
          (*cells)[i]->index(),
          &recovery_dofs);
        cell->get_dof_indices(dofs);
        const auto JxW = history->JxW((*cells)[i]);
        cell_mass      = 0;
        for (unsigned int q = 0; q < JxW.size(); ++q)
          for (unsigned int a = 0; a < n_nodes; ++a)
            cell_mass(a) += kinematics->shape_value(q, a) * JxW[q];
        constraints.distribute_local_to_global(cell_mass, dofs, lumped_mass);
        for (unsigned int a = 0; a < n_nodes; ++a)
          {
            node_indices[i * n_nodes + a] = dofs[a];
            node_locals[i * n_nodes + a]
              = lumped_mass.get_partitioner()->global_to_local(dofs[a]);
            has_constraints[i]
              = has_constraints[i] || constraints.is_constrained(dofs[a]);
          }
      }
    lumped_mass.compress(VectorOperation::add);
  }



  template <int dim>
  void
  ErrorEstimator<dim>::evaluate_points(const std::size_t i,
                                       const double     *entries,
                                       PointValues      &values) const
  {
    // The strain, damage gradient and damage of the solution at the points
    // of cell i (zeta = 1 without damage).
    const auto        &cell = (*cells)[i];
    const unsigned int n_q  = history->JxW(cell).size();
    kinematics->strains(cell,
                        entries,
                        make_array_view(&values.strains[0],
                                        &values.strains[0] + n_q));
    values.damage.fill(1.);
    if (with_damage)
      {
        kinematics->damage_gradients(
          cell,
          entries,
          make_array_view(&values.gradients[0], &values.gradients[0] + n_q));
        kinematics->damage(cell,
                           entries,
                           make_array_view(&values.damage[0],
                                           &values.damage[0] + n_q));
      }
  }



  template <int dim>
  void
  ErrorEstimator<dim>::cell_moments(const std::size_t i,
                                    const double     *entries,
                                    double           *moments) const
  {
    // int_K phi_a q_h for every node a of cell i and every component q of
    // the recovered fields, at moments[block * n_nodes + a].
    const auto        &cell    = (*cells)[i];
    const auto         points  = history->get_data(cell);
    const auto         JxW     = history->JxW(cell);
    const unsigned int n_q     = JxW.size();
    const unsigned int n_nodes = recovery_fe->n_dofs_per_cell();
    PointValues        values;
    evaluate_points(i, entries, values);
    const auto &strains   = values.strains;
    const auto &gradients = values.gradients;
    std::fill(moments, moments + recovered.n_blocks() * n_nodes, 0.);
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int a = 0; a < n_nodes; ++a)
        {
          const double w = kinematics->shape_value(q, a) * JxW[q];
          for (unsigned int c = 0; c < n_tensor<dim>; ++c)
            {
              moments[c * n_nodes + a]
                += w * points[q].stress.access_raw_entry(c);
              moments[(n_tensor<dim> + c) * n_nodes + a]
                += w * strains[q].access_raw_entry(c);
            }
          if (with_damage)
            for (unsigned int d = 0; d < dim; ++d)
              moments[(2 * n_tensor<dim> + d) * n_nodes + a]
                += w * gradients[q][d];
        }
  }



  template <int dim>
  void
  ErrorEstimator<dim>::project_to_nodes(const double *entries)
  {
    // sum_K int_K phi_i q_h for every component q of the recovered fields,
    // divided by the lumped mass; hanging nodes then take their parents'
    // average.
    recovered = 0;
    // The cells' integrals in the threads, each into its own slice of
    // moments, then added into the nodes in the cells' order.
    const unsigned int  n_nodes  = recovery_fe->n_dofs_per_cell();
    const unsigned int  n_blocks = recovered.n_blocks();
    std::vector<double> moments(cells->size() * n_blocks * n_nodes);
    parallel::apply_to_subranges(
      std::size_t(0),
      cells->size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          cell_moments(i, entries, &moments[i * n_blocks * n_nodes]);
      },
      64);
    std::vector<types::global_dof_index> dofs(n_nodes);
    Vector<double>                       cell_vector(n_nodes);
    for (std::size_t i = 0; i < cells->size(); ++i)
      {
        const double *cell_moments = &moments[i * n_blocks * n_nodes];
        // Most cells have no hanging node: their sums go straight into the
        // local storage; the others through the constraints.
        if (!has_constraints[i])
          for (unsigned int b = 0; b < n_blocks; ++b)
            for (unsigned int a = 0; a < n_nodes; ++a)
              recovered.block(b).local_element(node_locals[i * n_nodes + a])
                += cell_moments[b * n_nodes + a];
        else
          {
            std::copy_n(node_indices.begin() + i * n_nodes,
                        n_nodes,
                        dofs.begin());
            for (unsigned int b = 0; b < n_blocks; ++b)
              {
                std::copy_n(cell_moments + b * n_nodes,
                            n_nodes,
                            cell_vector.begin());
                constraints.distribute_local_to_global(cell_vector,
                                                       dofs,
                                                       recovered.block(b));
              }
          }
      }
    recovered.compress(VectorOperation::add);
    for (unsigned int b = 0; b < recovered.n_blocks(); ++b)
      {
        auto &block = recovered.block(b);
        for (unsigned int j = 0; j < block.locally_owned_size(); ++j)
          if (lumped_mass.local_element(j) > 0)
            block.local_element(j) /= lumped_mass.local_element(j);
        constraints.distribute(block);
      }
    recovered.update_ghost_values();
  }



  template <int dim>
  void
  ErrorEstimator<dim>::recovered_values(const std::size_t        i,
                                        const unsigned int       q,
                                        SymmetricTensor<2, dim> &stress,
                                        SymmetricTensor<2, dim> &strain,
                                        Tensor<1, dim>          &gradient) const
  {
    // The recovered fields at point q of cell i: sum_a N_a(x_q) v_a.
    const unsigned int n_nodes = recovery_fe->n_dofs_per_cell();
    for (unsigned int a = 0; a < n_nodes; ++a)
      {
        const auto   node = node_locals[i * n_nodes + a];
        const double N    = kinematics->shape_value(q, a);
        for (unsigned int c = 0; c < n_tensor<dim>; ++c)
          {
            stress.access_raw_entry(c)
              += N * recovered.block(c).local_element(node);
            strain.access_raw_entry(c)
              += N * recovered.block(n_tensor<dim> + c).local_element(node);
          }
        if (with_damage)
          for (unsigned int d = 0; d < dim; ++d)
            gradient[d]
              += N * recovered.block(2 * n_tensor<dim> + d).local_element(node);
      }
  }



  template <int dim>
  typename ErrorEstimator<dim>::CellNorms
  ErrorEstimator<dim>::cell_norms(const std::size_t           i,
                                  const double               *entries,
                                  const ViscoplasticLaw<dim> &law,
                                  const bool                  initial)
  {
    // The squared distances between the recovered and the discrete fields
    // on cell i, and the squared norm of G_n - G_0 (at n = 0, G_0 is
    // stored instead).
    const auto        &cell   = (*cells)[i];
    const auto         points = history->get_data(cell);
    const auto         JxW    = history->JxW(cell);
    const unsigned int n_q    = JxW.size();
    PointValues        values;
    evaluate_points(i, entries, values);
    const auto &strains   = values.strains;
    const auto &gradients = values.gradients;
    const auto &damage    = values.damage;
    CellNorms   norms;
    for (unsigned int q = 0; q < n_q; ++q)
      {
        SymmetricTensor<2, dim> stress_star, strain_star;
        Tensor<1, dim>          gradient_star;
        recovered_values(i, q, stress_star, strain_star, gradient_star);
        const auto stress_error = stress_star - points[q].stress;
        const auto strain_error = strain_star - strains[q];
        norms.stress += scalar_product(stress_error, stress_error) * JxW[q];
        norms.strain += scalar_product(strain_error, strain_error) * JxW[q];
        if (with_damage)
          norms.damage += (gradient_star - gradients[q]).norm_square() * JxW[q];
        const auto rate = law.rate(points[q].stress, strains[q], damage[q]);
        if (initial)
          points[q].initial_rate = rate;
        const auto change = rate - points[q].initial_rate;
        norms.time += scalar_product(change, change) * JxW[q];
      }
    const double h_over_pi = cell->diameter() / numbers::PI;
    norms.damage *= h_over_pi * h_over_pi;
    return norms;
  }



  template <int dim>
  ErrorEstimate
  ErrorEstimator<dim>::estimate_step(const unsigned int          n,
                                     const double                k,
                                     const double               *entries,
                                     const ViscoplasticLaw<dim> &law,
                                     const double                youngs_modulus)
  {
    project_to_nodes(entries);
    // The cells' norms in the threads, then summed in the cells' order (the
    // same bits with any number of threads).
    std::vector<CellNorms> norms(cells->size());
    parallel::apply_to_subranges(
      std::size_t(0),
      cells->size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          norms[i] = cell_norms(i, entries, law, n == 0);
      },
      64);
    double sums[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < norms.size(); ++i)
      {
        const CellNorms &c = norms[i];
        sums[0] += c.stress;
        sums[1] += c.strain;
        sums[2] += c.damage;
        sums[3] += c.time;
        const float eta
          = std::sqrt(c.stress) + std::sqrt(c.strain) + std::sqrt(c.damage);
        const unsigned int index = (*cells)[i]->active_cell_index();
        indicators[index]        = std::max(indicators[index], eta);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 4),
                        triangulation->get_communicator(),
                        ArrayView<double>(sums, 4));
    ErrorEstimate estimate;
    estimate.space
      = std::sqrt(sums[0]) + std::sqrt(sums[1]) + std::sqrt(sums[2]);
    estimate.time = (1. + 1. / youngs_modulus) * 0.5 * k * std::sqrt(sums[3]);
    if (estimate.sum() > largest_sum.sum())
      largest_sum = estimate;
    largest_part.space = std::max(largest_part.space, estimate.space);
    largest_part.time  = std::max(largest_part.time, estimate.time);
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
  std::map<std::string, double>
  ErrorEstimator<dim>::running_maxima() const
  {
    return {{"estimate_space", largest_sum.space},
            {"estimate_time", largest_sum.time},
            {"estimate_space_max", largest_part.space},
            {"estimate_time_max", largest_part.time}};
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
    largest_part = {value("estimate_space_max"), value("estimate_time_max")};
  }



  template class ErrorEstimator<2>;
  template class ErrorEstimator<3>;
} // namespace VPContact
