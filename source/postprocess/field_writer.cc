// FieldWriter: the .vtu piece of a field output, compressed and written in a
// thread of its own or at once.
#include <vpcontact/postprocess/field_writer.h>
#include <vpcontact/postprocess/output_writer.h>
#include <vpcontact/postprocess/vtu_cell_data.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <memory>
#include <sstream>
#include <utility>

namespace VPContact
{
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
    auto task
      = [fields = std::make_shared<FieldPatches<dim>>(std::move(fields)),
         filename,
         flags]() mutable -> std::string {
      std::string problem;
      try
        {
          if (fields->build)
            fields->build(fields->patches);
          const std::string cell_data
            = take_cell_data(fields->patches, fields->cell_names);
          std::ostringstream vtu;
          DataOutBase::write_vtu(fields->patches,
                                 fields->names,
                                 fields->vector_ranges,
                                 flags,
                                 vtu);
          write_file_atomically(filename,
                                cell_data.empty() ?
                                  vtu.str() :
                                  insert_cell_data(vtu.str(), cell_data));
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
      write = std::async(std::launch::async, std::move(task));
    else
      failure = task();
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
