// The cores of a rank and the two halves of its cells (see cell_halves.h).
#include <vpcontact/cell_halves.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <thread>

#ifdef __linux__
#  include <sched.h>
#endif

namespace VPContact
{
  unsigned int
  cores_per_rank(const MPI_Comm communicator)
  {
    unsigned int cores = std::thread::hardware_concurrency();
#ifdef __linux__
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
      cores = CPU_COUNT(&set);
#endif
    // Unbound ranks on one node each see all of its cores: share them.
    MPI_Comm  node;
    const int error = MPI_Comm_split_type(communicator,
                                          MPI_COMM_TYPE_SHARED,
                                          0,
                                          MPI_INFO_NULL,
                                          &node);
    AssertThrowMPI(error);
    const unsigned int ranks_on_node = Utilities::MPI::n_mpi_processes(node);
    Utilities::MPI::free_communicator(node);
    return std::max(1u, cores / ranks_on_node);
  }



  template <int dim>
  void
  CellHalves<dim>::reinit(const DoFHandler<dim> &dof_handler)
  {
    cells.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cells.push_back(cell);
    middle = cells.size() / 2;
  }



  template <int dim>
  ArrayView<const typename CellHalves<dim>::cell_iterator>
  CellHalves<dim>::half(const unsigned int h) const
  {
    AssertIndexRange(h, 2);
    return h == 0 ? make_array_view(cells.data(), cells.data() + middle) :
                    make_array_view(cells.data() + middle,
                                    cells.data() + cells.size());
  }



  template <int dim>
  ArrayView<const typename CellHalves<dim>::cell_iterator>
  CellHalves<dim>::chunk(const unsigned int c,
                         const unsigned int n_chunks) const
  {
    AssertIndexRange(c, n_chunks);
    const std::size_t n = cells.size();
    return make_array_view(cells.data() + c * n / n_chunks,
                           cells.data() + (c + 1) * n / n_chunks);
  }



  template <int dim>
  unsigned int
  CellHalves<dim>::size() const
  {
    return cells.size();
  }



  void
  WorkAhead::restart()
  {
    arrived.store(false, std::memory_order_release);
    done = 0;
  }



  void
  WorkAhead::arrive()
  {
    arrived.store(true, std::memory_order_release);
  }



  unsigned int
  WorkAhead::take_done()
  {
    const unsigned int n = done;
    restart();
    return n;
  }



  template class CellHalves<2>;
  template class CellHalves<3>;
} // namespace VPContact
