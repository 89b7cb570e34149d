// The locally owned cells in two halves that two threads work on at once, for
// the passes over all cells that every time step makes.
#ifndef vpcontact_cell_halves_h
#define vpcontact_cell_halves_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>

#include <array>
#include <atomic>
#include <future>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The cores this process may run on (its CPU affinity: mpirun binds each
   * rank to one core by default) divided by the ranks of @p communicator on
   * its node, at least 1. Collective.
   */
  unsigned int
  cores_per_rank(const MPI_Comm communicator);

  /**
   * {work(0), work(1)}: work(1) in a second thread while work(0) runs in the
   * calling one if @p two_threads, else one after the other. Either way the
   * same two calls are made, so a result that depends only on what each
   * call computes is the same bits with one thread or two. work(1) must
   * call no MPI function (MPI is initialized for one calling thread at a
   * time), and the two calls must not write the same data. An exception of
   * either reaches the caller, after both have ended.
   */
  template <typename Work>
  auto
  run_in_halves(const bool two_threads, const Work &work)
  {
    using Result = decltype(work(0u));
    if (!two_threads)
      return std::array<Result, 2>{{work(0u), work(1u)}};
    // Should work(0) throw, the future's destructor waits for work(1).
    auto         second = std::async(std::launch::async, work, 1u);
    const Result first  = work(0u);
    return std::array<Result, 2>{{first, second.get()}};
  }

  /**
   * The locally owned cells of a DoFHandler in their order, cut at the
   * middle: run_in_halves() over half(0) and half(1) visits each cell once.
   * The passes over all cells in every step (the stress update, the
   * statistics) read the state of their own cell and write only to it or to
   * a reduction, so the two halves need no coordination. Once per mesh.
   */
  template <int dim>
  class CellHalves
  {
  public:
    using cell_iterator = typename DoFHandler<dim>::active_cell_iterator;

    void
    reinit(const DoFHandler<dim> &dof_handler);

    /// The cells of half @p h (0 or 1).
    ArrayView<const cell_iterator>
    half(const unsigned int h) const;

    /// The cells of chunk @p c of @p n_chunks of about equal size, in
    /// order.
    ArrayView<const cell_iterator>
    chunk(const unsigned int c, const unsigned int n_chunks) const;

    /// The number of cells.
    unsigned int
    size() const;

  private:
    std::vector<cell_iterator> cells;
    unsigned int               middle = 0;
  };



  /**
   * A pass in chunks that the second thread may begin while the calling
   * thread is still busy with other work, and the calling thread finishes.
   * The second thread runs chunk after chunk (run_ahead()) until all are
   * done or the calling thread has said it is free (arrive()); once the
   * second thread has ended, take_done() tells the calling thread how many
   * chunks are done, and it runs the others. Each chunk must write only its
   * own data, so that the result does not depend on who ran it.
   */
  class WorkAhead
  {
  public:
    /// Nothing done: the pass starts over (its input has changed).
    void
    restart();

    /// In the second thread: work(c) for c = 0, 1, ..., n_chunks - 1, until
    /// the calling thread arrives.
    template <typename Work>
    void
    run_ahead(const unsigned int n_chunks, const Work &work)
    {
      while (done < n_chunks && !arrived.load(std::memory_order_acquire))
        work(done++);
    }

    /// In the calling thread: free to do the rest; run_ahead() stops
    /// after the chunk it is working on.
    void
    arrive();

    /// In the calling thread, after the second thread has ended: the
    /// number of chunks done ahead; the pass starts over for the next time.
    unsigned int
    take_done();

  private:
    std::atomic<bool> arrived{false};
    unsigned int      done = 0;
  };
} // namespace VPContact

#endif
