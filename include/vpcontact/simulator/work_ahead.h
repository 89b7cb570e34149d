// WorkAhead: a pass in chunks that a second thread may begin while the
// calling thread is busy with other work, and that the calling thread
// finishes.
#ifndef vpcontact_work_ahead_h
#define vpcontact_work_ahead_h

#include <atomic>

namespace VPContact
{
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
    restart()
    {
      arrived.store(false, std::memory_order_release);
      done = 0;
    }

    /// In the second thread: work(c) for c = done, done + 1, ...,
    /// n_chunks - 1, until the calling thread arrives.
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
    arrive()
    {
      arrived.store(true, std::memory_order_release);
    }

    /// In the calling thread, after the second thread has ended: the
    /// number of chunks done ahead; the pass starts over for the next time.
    unsigned int
    take_done()
    {
      const unsigned int n = done;
      restart();
      return n;
    }

  private:
    std::atomic<bool> arrived{false};
    unsigned int      done = 0;
  };
} // namespace VPContact

#endif
