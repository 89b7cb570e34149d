// Carrying the nodal vectors and the quadrature point history of a run
// through a change of its distributed mesh.
#include <vpcontact/refinement/mesh_transfer.h>

#include <cstring>

namespace VPContact
{
  template <int dim>
  MeshTransfer<dim>::MeshTransfer(
    parallel::distributed::Triangulation<dim> &triangulation,
    const DoFHandler<dim>                     &dof_handler,
    const Quadrature<dim>                     &quadrature)
    : mesh(triangulation)
    , solution(dof_handler)
    , fields(quadrature)
  {}



  template <int dim>
  std::vector<double>
  MeshTransfer<dim>::values_of(const StressHistory<dim> &history,
                               const cell_iterator      &cell) const
  {
    constexpr unsigned int n_values = QuadraturePointHistory<dim>::n_values;
    const auto             points   = history.get_data(cell);
    const auto             rates    = history.initial_rates(cell);
    const auto             sources  = history.damage_sources(cell);
    std::vector<double>    values(points.size() * n_values);
    for (unsigned int q = 0; q < points.size(); ++q)
      points[q].write_to(&values[q * n_values], rates[q], sources[q]);
    return values;
  }



  template <int dim>
  void
  MeshTransfer<dim>::store(const std::vector<double> &values,
                           StressHistory<dim>        &history,
                           const cell_iterator       &cell) const
  {
    constexpr unsigned int n_values = QuadraturePointHistory<dim>::n_values;
    const auto             points   = history.get_data(cell);
    const auto             rates    = history.initial_rates(cell);
    const auto             sources  = history.damage_sources(cell);
    AssertDimension(values.size(), points.size() * n_values);
    for (unsigned int q = 0; q < points.size(); ++q)
      points[q].read_from(&values[q * n_values], rates[q], sources[q]);
  }



  template <int dim>
  void
  MeshTransfer<dim>::prepare(
    const std::vector<const LA::MPI::Vector *> &vectors,
    const StressHistory<dim>                   &history)
  {
    solution.prepare_for_coarsening_and_refinement(vectors);

    // A cell to be coarsened away is packed as its parent, with the
    // children's fields projected onto it; any other cell packs its own
    // (a cell to be refined is split when unpacked, on its new owner).
    // Every cell sends the same number of bytes.
    constexpr unsigned int n_values = QuadraturePointHistory<dim>::n_values;
    handle                          = mesh.register_data_attach(
      [this, &history](const cell_iterator                          &cell,
                       const typename Triangulation<dim>::CellStatus status) {
        std::vector<double> values;
        if (status == Triangulation<dim>::CELL_COARSEN)
          {
            std::vector<double> children;
            for (unsigned int c = 0; c < cell->n_children(); ++c)
              {
                const std::vector<double> child
                  = values_of(history, cell->child(c));
                children.insert(children.end(), child.begin(), child.end());
              }
            fields.coarsen(children, n_values, values);
          }
        else
          values = values_of(history, cell);
        std::vector<char> bytes(values.size() * sizeof(double));
        std::memcpy(bytes.data(), values.data(), bytes.size());
        return bytes;
      },
      false);
  }



  template <int dim>
  void
  MeshTransfer<dim>::unpack(const std::vector<LA::MPI::Vector *> &vectors,
                            StressHistory<dim>                   &history)
  {
    std::vector<LA::MPI::Vector *> out(vectors);
    solution.interpolate(out);

    constexpr unsigned int n_values = QuadraturePointHistory<dim>::n_values;
    history.keep_initial_rates();
    mesh.notify_ready_to_unpack(
      handle,
      [this, &history](
        const cell_iterator                                            &cell,
        const typename Triangulation<dim>::CellStatus                   status,
        const boost::iterator_range<std::vector<char>::const_iterator> &bytes) {
        std::vector<double> values(bytes.size() / sizeof(double));
        std::memcpy(values.data(), &*bytes.begin(), bytes.size());
        if (status == Triangulation<dim>::CELL_REFINE)
          {
            std::vector<double> child;
            for (unsigned int c = 0; c < cell->n_children(); ++c)
              {
                fields.refine(values, n_values, c, child);
                store(child, history, cell->child(c));
              }
          }
        else
          store(values, history, cell);
      });
  }



  template class MeshTransfer<2>;
  template class MeshTransfer<3>;
} // namespace VPContact
