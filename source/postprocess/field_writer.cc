// FieldWriter: the .vtu piece of a field output, compressed and written in a
// thread of its own or at once.
#include <vpcontact/postprocess/field_writer.h>
#include <vpcontact/postprocess/output_writer.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <memory>
#include <sstream>
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
    // leave of the cores. Where the rank has several threads, the thread
    // takes the lowest scheduling priority (on Linux, a thread's nice value
    // is its own): the steps' parallel loops fill the cores, their serial
    // parts leave some idle, and the write runs there, or in full when the
    // next output or the end of the run waits for it. A rank of one thread
    // (several ranks on as many cores) has no idle core: OutputWriter
    // writes at once there, and a write started in the background keeps
    // the priority (the waits for the other ranks are spent polling, and a
    // write at the lowest priority would only run once the next output
    // waits for it).
    template <typename Work>
    void
    run_yielding_to_steps(const Work &work)
    {
#ifdef __linux__
      if (MultithreadInfo::n_threads() > 1)
        setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 19);
#endif
      work();
    }

    // Compress and write the piece, array by array, into a temporary file
    // that becomes the piece once it is whole.
    void
    write_piece_file(const FieldPiece &fields, const std::string &filename)
    {
      write_file_atomically(filename, [&](std::ostream &out) {
        fields.piece.write(out);
      });
    }
  } // namespace



  FieldWriter::~FieldWriter()
  {
    // A run that stops with an error leaves its last piece whole: wait
    // for it. What went wrong with it no longer matters then.
    if (write.valid())
      write.wait();
  }



  void
  FieldWriter::start(FieldPiece       &&fields,
                     const std::string &filename,
                     const bool         in_background)
  {
    Assert(!pending(), ExcMessage("wait() for the previous write first"));
    // A write at once holds up the steps, and there the kept sections of
    // the mesh save their compression. A write in the background runs on
    // a core the steps leave idle: the sections would only hold memory
    // there.
    const bool          keep_sections = !in_background;
    const std::uint64_t fingerprint
      = keep_sections ? fields.piece.mesh_fingerprint() : 0;
    if (!keep_sections)
      mesh_sections.reset();
    else if (mesh_sections != nullptr && fingerprint == mesh_fingerprint)
      fields.piece.reuse_mesh_sections(mesh_sections);
    // The task owns the piece. It holds the piece through a shared pointer, so
    // that no copy of the task copies it, and frees it itself. It returns
    // what went wrong, or an empty string.
    auto write_piece
      = [this,
         fields = std::make_shared<FieldPiece>(std::move(fields)),
         filename,
         keep_sections,
         fingerprint]() mutable -> std::string {
      std::string problem;
      try
        {
          if (keep_sections && !fields->piece.has_mesh_sections())
            {
              // A new mesh: its sections, for this piece and the next
              // (the task runs at once here, in the caller's thread).
              mesh_sections    = fields->piece.take_mesh_sections();
              mesh_fingerprint = fingerprint;
            }
          write_piece_file(*fields, filename);
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



  bool
  FieldWriter::pending() const
  {
    return started;
  }



  std::string
  FieldWriter::wait()
  {
    if (!started)
      return "";
    started = false;
    if (write.valid())
      failure = write.get();
    return failure;
  }



} // namespace VPContact
