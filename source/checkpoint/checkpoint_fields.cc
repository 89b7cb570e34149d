// Writing and reading the fields of a checkpoint with the distributed mesh.
#include <vpcontact/checkpoint/checkpoint_fields.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/distributed/solution_transfer.h>

#include <cstring>

namespace VPContact
{
  namespace CheckpointFields
  {
    template <int dim>
    void
    save(parallel::distributed::Triangulation<dim>  &triangulation,
         const DoFHandler<dim>                      &dof_handler,
         const std::vector<const LA::MPI::Vector *> &vectors,
         const StressHistory<dim>                   &history,
         const unsigned int                          n_q_points,
         const std::string                          &filename)
    {
      // The transfer object registers its callback now and must live until
      // save() has called it.
      parallel::distributed::SolutionTransfer<dim, LA::MPI::Vector>
        solution_transfer(dof_handler);
      solution_transfer.prepare_for_serialization(vectors);

      // The history of a cell as raw bytes: n_q_points blocks of n_values
      // doubles. Every cell returns the same size, so deal.II stores it in
      // its fixed-size section and can find a cell's data by its position.
      constexpr unsigned int n_values = QuadraturePointHistory<dim>::n_values;
      triangulation.register_data_attach(
        [&history,
         n_q_points](const typename Triangulation<dim>::cell_iterator &cell,
                     const typename Triangulation<dim>::CellStatus) {
          const auto points  = history.get_data(cell);
          const auto rates   = history.initial_rates(cell);
          const auto sources = history.damage_sources(cell);
          AssertDimension(points.size(), n_q_points);
          std::vector<double> values(n_q_points * n_values);
          for (unsigned int q = 0; q < n_q_points; ++q)
            points[q].write_to(&values[q * n_values], rates[q], sources[q]);
          std::vector<char> bytes(values.size() * sizeof(double));
          std::memcpy(bytes.data(), values.data(), bytes.size());
          return bytes;
        },
        false);

      triangulation.save(filename);
    }



    template <int dim>
    void
    load(parallel::distributed::Triangulation<dim> &triangulation,
         const DoFHandler<dim>                     &dof_handler,
         const std::vector<LA::MPI::Vector *>      &vectors,
         StressHistory<dim>                        &history,
         const unsigned int                         n_q_points)
    {
      // In the order of save(): each party registers again and unpacks.
      parallel::distributed::SolutionTransfer<dim, LA::MPI::Vector>
                                     solution_transfer(dof_handler);
      std::vector<LA::MPI::Vector *> out(vectors);
      solution_transfer.deserialize(out);

      constexpr unsigned int n_values = QuadraturePointHistory<dim>::n_values;
      const unsigned int     handle   = triangulation.register_data_attach(
        [](const typename Triangulation<dim>::cell_iterator &,
           const typename Triangulation<dim>::CellStatus) {
          return std::vector<char>();
        },
        false);
      history.keep_initial_rates();
      triangulation.notify_ready_to_unpack(
        handle,
        [&history, n_q_points](
          const typename Triangulation<dim>::cell_iterator &cell,
          const typename Triangulation<dim>::CellStatus,
          const boost::iterator_range<std::vector<char>::const_iterator>
            &bytes) {
          // A checkpoint of another quadrature rule or history layout has
          // another size per cell: refuse it rather than misread it.
          AssertThrow(static_cast<std::size_t>(bytes.size())
                        == n_q_points * n_values * sizeof(double),
                      ExcMessage(
                        "The quadrature point data of a cell in the "
                        "checkpoint has "
                        + std::to_string(bytes.size())
                        + " bytes, this program expects "
                        + std::to_string(n_q_points * n_values * sizeof(double))
                        + ": the checkpoint was written by another version "
                          "of the program."));
          std::vector<double> values(n_q_points * n_values);
          std::memcpy(values.data(), &*bytes.begin(), bytes.size());
          const auto points  = history.get_data(cell);
          const auto rates   = history.initial_rates(cell);
          const auto sources = history.damage_sources(cell);
          AssertDimension(points.size(), n_q_points);
          for (unsigned int q = 0; q < n_q_points; ++q)
            points[q].read_from(&values[q * n_values], rates[q], sources[q]);
        });
    }



    template <int dim>
    std::map<std::string, std::uintmax_t>
    expected_sizes(
      const parallel::distributed::Triangulation<dim> &triangulation,
      const std::string                               &name,
      const std::size_t                                bytes_per_cell)
    {
      // deal.II's layout: the cumulative sizes of the fixed-size
      // attachments (one unsigned int per attachment, and one more), then
      // every cell's record in the order of the cells. save() attaches two:
      // the vectors (SolutionTransfer) and the stress history.
      constexpr unsigned int n_attachments = 2;
      const std::uintmax_t header = sizeof(unsigned int) * (n_attachments + 1);
      return {{name + "_fixed.data",
               header
                 + std::uintmax_t(triangulation.n_global_active_cells())
                     * bytes_per_cell}};
    }



    template void
    save(parallel::distributed::Triangulation<2> &,
         const DoFHandler<2> &,
         const std::vector<const LA::MPI::Vector *> &,
         const StressHistory<2> &,
         const unsigned int,
         const std::string &);
    template void
    save(parallel::distributed::Triangulation<3> &,
         const DoFHandler<3> &,
         const std::vector<const LA::MPI::Vector *> &,
         const StressHistory<3> &,
         const unsigned int,
         const std::string &);
    template std::map<std::string, std::uintmax_t>
    expected_sizes(const parallel::distributed::Triangulation<2> &,
                   const std::string &,
                   const std::size_t);
    template std::map<std::string, std::uintmax_t>
    expected_sizes(const parallel::distributed::Triangulation<3> &,
                   const std::string &,
                   const std::size_t);
    template void
    load(parallel::distributed::Triangulation<2> &,
         const DoFHandler<2> &,
         const std::vector<LA::MPI::Vector *> &,
         StressHistory<2> &,
         const unsigned int);
    template void
    load(parallel::distributed::Triangulation<3> &,
         const DoFHandler<3> &,
         const std::vector<LA::MPI::Vector *> &,
         StressHistory<3> &,
         const unsigned int);
  } // namespace CheckpointFields
} // namespace VPContact
