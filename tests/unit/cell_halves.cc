// Unit test: CellHalves and run_in_halves(), serial and on 2 ranks. On a
// locally refined distributed mesh the two halves hold every locally owned
// cell once, in order; run_in_halves() returns {work(0), work(1)} with one
// thread and with two, runs work(1) in another thread only with two, and
// hands an exception of either half to the caller once both have ended.
// The chunks hold every owned cell once, in order; WorkAhead's second
// thread runs chunks until the caller arrives, and the caller the rest.
#include <vpcontact/cell_halves.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>

using namespace VPContact;

namespace
{
  const char *
  yes_no(const bool value)
  {
    return value ? "yes" : "no";
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const bool root   = Utilities::MPI::this_mpi_process(comm) == 0;
  const auto report = [&](const std::string &what, const bool value) {
    const bool everywhere = Utilities::MPI::min(value ? 1 : 0, comm) == 1;
    if (root)
      std::printf("%s: %s\n", what.c_str(), yes_no(everywhere));
  };

  // A unit square refined three times, then once more near a corner, so
  // that the cells are not all on one level.
  parallel::distributed::Triangulation<2> triangulation(comm);
  GridGenerator::hyper_cube(triangulation);
  triangulation.refine_global(3);
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned() && cell->center()[0] + cell->center()[1] < 0.5)
      cell->set_refine_flag();
  triangulation.execute_coarsening_and_refinement();
  DoFHandler<2> dof_handler(triangulation);
  dof_handler.distribute_dofs(FE_Q<2>(1));

  CellHalves<2> halves;
  halves.reinit(dof_handler);
  std::vector<unsigned int> visits(triangulation.n_active_cells(), 0);
  std::vector<unsigned int> order;
  for (unsigned int h = 0; h < 2; ++h)
    for (const auto &cell : halves.half(h))
      {
        ++visits[cell->active_cell_index()];
        order.push_back(cell->active_cell_index());
      }
  bool once = true;
  for (const auto &cell : dof_handler.active_cell_iterators())
    once = once
           && visits[cell->active_cell_index()]
                == (cell->is_locally_owned() ? 1u : 0u);
  report("every owned cell in one half, once", once);
  report("in the order of the cells",
         std::is_sorted(order.begin(), order.end()));
  report("halves of equal size (to one cell)",
         halves.half(1).size() - halves.half(0).size() <= 1);

  // The results of the two calls, and the thread each ran in.
  const auto caller = std::this_thread::get_id();
  for (const bool two_threads : {false, true})
    {
      std::array<std::thread::id, 2> thread;
      const auto   sums = run_in_halves(two_threads, [&](const unsigned int h) {
        thread[h]  = std::this_thread::get_id();
        double sum = 0;
        for (const auto &cell : halves.half(h))
          sum += cell->measure();
        return sum;
      });
      const double area = Utilities::MPI::sum(sums[0] + sums[1], comm);
      const std::string with = two_threads ? "two threads" : "one thread";
      report(with + ": the halves add up to the area",
             std::abs(area - 1.) < 1e-14);
      report(with + ": the first half in the calling thread",
             thread[0] == caller);
      report(with + ": the second half in another thread", thread[1] != caller);
    }

  // An exception of either half reaches the caller; when the first half
  // throws, only after the second has ended.
  for (const unsigned int thrower : {0u, 1u})
    {
      std::atomic<bool> second_ended{false};
      bool              caught = false;
      try
        {
          run_in_halves(true, [&](const unsigned int h) {
            if (h == 1)
              std::this_thread::sleep_for(std::chrono::milliseconds(50));
            if (h == thrower)
              throw std::runtime_error("half " + std::to_string(h));
            if (h == 1)
              second_ended = true;
            return 0;
          });
        }
      catch (const std::runtime_error &e)
        {
          caught = (e.what() == "half " + std::to_string(thrower));
        }
      report("an exception of half " + std::to_string(thrower)
               + " reaches the caller",
             caught);
      if (thrower == 0)
        report("  after the second half has ended", second_ended);
    }

  // Chunks: every owned cell in one chunk, once and in order, for fewer
  // and for more chunks than cells.
  for (const unsigned int n_chunks : {1u, 7u, 1000u})
    {
      std::vector<unsigned int> chunked;
      for (unsigned int c = 0; c < n_chunks; ++c)
        for (const auto &cell : halves.chunk(c, n_chunks))
          chunked.push_back(cell->active_cell_index());
      report(std::to_string(n_chunks)
               + " chunks: every owned cell once, in "
                 "order",
             chunked == order && halves.size() == order.size());
    }

  // WorkAhead: the second thread runs chunks until the caller arrives; the
  // caller then runs the rest. Whoever ran a chunk, each is run once and
  // the areas add up.
  constexpr unsigned int n_chunks = 64;
  WorkAhead              ahead;
  for (const std::string when : {"never", "at once", "midway"})
    {
      std::vector<double>       area(n_chunks, 0.);
      std::vector<unsigned int> runs(n_chunks, 0);
      const auto                work = [&](const unsigned int c) {
        ++runs[c];
        for (const auto &cell : halves.chunk(c, n_chunks))
          area[c] += cell->measure();
        if (when == "midway" && c == n_chunks / 2)
          ahead.arrive();
      };
      ahead.restart();
      if (when == "at once")
        ahead.arrive();
      std::thread second([&]() { ahead.run_ahead(n_chunks, work); });
      second.join();
      const unsigned int done = ahead.take_done();
      for (unsigned int c = done; c < n_chunks; ++c)
        work(c);
      const double total
        = Utilities::MPI::sum(std::accumulate(area.begin(), area.end(), 0.),
                              comm);
      report("ahead, caller arriving " + when + ": "
               + (when == "never"   ? "all chunks ahead" :
                  when == "at once" ? "none ahead" :
                                      "the chunks up to the arrival ahead"),
             done
               == (when == "never"   ? n_chunks :
                   when == "at once" ? 0u :
                                       n_chunks / 2 + 1));
      report("  every chunk run once, the areas add up",
             std::all_of(runs.begin(), runs.end(), [](const unsigned int r) {
               return r == 1;
             }) && std::abs(total - 1.) < 1e-14);
      report("  the next pass starts over", ahead.take_done() == 0);
    }

  report("cores per rank at least 1", cores_per_rank(comm) >= 1);
}
