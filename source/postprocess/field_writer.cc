// FieldWriter: the .vtu piece of a field output, compressed and written in a
// thread of its own or at once.
#include <vpcontact/postprocess/field_writer.h>
#include <vpcontact/postprocess/output_writer.h>
#include <vpcontact/postprocess/vtu_cell_data.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <memory>
#include <sstream>
#include <tbb/task_arena.h>
#include <utility>

#ifdef __linux__
#  include <sys/resource.h>
#  include <sys/syscall.h>
#  include <unistd.h>
#endif

namespace VPContact
{
  namespace
  {
    // Runs @p work, a write in the background, on what the time steps
    // leave of the cores. deal.II's parallel loops inside the work
    // (DataOut's WorkStream over the cells) run in an arena of this one
    // thread: a TBB worker would otherwise take a share of them and leave
    // the steps' own parallel loops a thread short. Where the rank has
    // several threads, the thread also takes the lowest scheduling priority
    // (on Linux, a thread's nice value is its own): the steps' parallel
    // loops fill the cores, their serial parts leave some idle, and the
    // write runs there, or in full when the next output or the end of the
    // run waits for it. A rank of one thread (several ranks on as many
    // cores) has no idle core: OutputWriter writes at once there, and a
    // write started in the background keeps the priority (the waits for
    // the other ranks are spent polling, and a write at the lowest
    // priority would only run once the next output waits for it).
    template <typename Work>
    void
    run_yielding_to_steps(const Work &work)
    {
#ifdef __linux__
      if (MultithreadInfo::n_threads() > 1)
        setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
      tbb::task_arena one_thread(1);
      one_thread.execute(work);
    }

    // Build (where FieldPatches::build is set), compress and write the
    // piece; frees the patches (resets @p fields) as soon as write_vtu()
    // has compressed them: the compressed piece is a fraction of their
    // size, and its text is then copied out of the stream and into the file
    // without them.
    template <int dim>
    void
    write_piece_file(std::shared_ptr<FieldPatches<dim>> &fields,
                     const std::string                  &filename,
                     const DataOutBase::VtkFlags        &flags)
    {
      if (fields->build)
        fields->build(fields->patches);
      const std::string cell_data
        = take_cell_data(fields->patches, fields->cell_names);
      std::string vtu;
      {
        std::ostringstream stream;
        DataOutBase::write_vtu(fields->patches,
                               fields->names,
                               fields->vector_ranges,
                               flags,
                               stream);
        fields.reset();
        vtu = stream.str();
      }
      write_file_atomically(filename, [&](std::ostream &out) {
        write_with_cell_data(out, vtu, cell_data);
      });
    }
  } // namespace



  template <int dim>
  FieldWriter<dim>::~FieldWriter()
  {
    // A run that stops with an error leaves its last piece whole: wait
    // for it. What went wrong with it no longer matters then.
    if (write.valid())
      write.wait();
  }



  template <int dim>
  void
  FieldWriter<dim>::start(FieldPatches<dim>          &&fields,
                          const std::string           &filename,
                          const DataOutBase::VtkFlags &flags,
                          const bool                   in_background)
  {
    Assert(!pending(), ExcMessage("wait() for the previous write first"));
    // The task owns the patches (or what builds them); the file is written
    // only once the whole piece is in memory. It holds them through a shared
    // pointer, so that no copy of the task copies them (a copy of the patches
    // would double the memory of the output at its peak), and frees them
    // itself: freed by the thread that waits for the write, they would cost
    // that thread the time of returning every patch's memory. It returns
    // what went wrong, or an empty string.
    auto write_piece
      = [fields = std::make_shared<FieldPatches<dim>>(std::move(fields)),
         filename,
         flags]() mutable -> std::string {
      std::string problem;
      try
        {
          write_piece_file(fields, filename, flags);
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          problem = Utilities::trim(info.str());
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
      fields.reset();
      return problem;
    };
    started = true;
    if (in_background)
      write = std::async(std::launch::async,
                         [write_piece = std::move(write_piece)]() mutable {
                           std::string problem;
                           run_yielding_to_steps(
                             [&]() { problem = write_piece(); });
                           return problem;
                         });
    else
      failure = write_piece();
  }



  template <int dim>
  bool
  FieldWriter<dim>::pending() const
  {
    return started;
  }



  template <int dim>
  std::string
  FieldWriter<dim>::wait()
  {
    if (!started)
      return "";
    started = false;
    if (write.valid())
      failure = write.get();
    return failure;
  }



  template class FieldWriter<2>;
  template class FieldWriter<3>;
} // namespace VPContact
