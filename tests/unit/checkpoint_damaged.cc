// Checks how a resumed run treats checkpoints that it must not trust or
// cannot use, on the scene of checkpoint_runner.h (a checkpoint every 4
// steps; SIGTERM during step 6 leaves the checkpoint of step 6 and, as
// fallback, that of step 4):
// - the newest checkpoint truncated (and an incomplete FOLDER.new left by a
//   run killed while writing): the run says so, resumes from the previous
//   complete checkpoint, and still ends exactly as the uninterrupted run;
// - a complete run resumed with the same end time: nothing left to do;
// - a checkpoint of another problem (another Young's modulus): refused,
//   naming the entry; a later end time is accepted and continues the run;
// - every checkpoint damaged (a changed byte, a missing file): refused,
//   naming each folder and file;
// - no checkpoint at all: refused, naming the folder.
// Checksums in the messages are masked (they depend on the bytes written).
#include <vpcontact/app/mpi_io_choice.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <regex>

#include "checkpoint_runner.h"

using namespace VPContact;

namespace
{
  // Resume the scene in @p directory with @p changes to its parameters;
  // print what the run said about its checkpoint, or why it refused.
  void
  resume(const std::string &directory,
         const std::string &changes,
         const std::string &what)
  {
    std::cout << "--- " << what << std::endl;
    ParameterHandler prm;
    set_checkpoint_scene(prm, directory, 4);
    prm.parse_input_from_string(changes);
    prm.enter_subsection("Checkpoint");
    prm.set("Resume from checkpoint", true);
    prm.leave_subsection();
    try
      {
        run_logged(prm, MPI_COMM_WORLD, directory + ".log");
        for (const auto &line : read_lines(directory + ".log"))
          if (line.rfind("Checkpoint:", 0) == 0
              || line.rfind("Resuming", 0) == 0
              || line.rfind("Run complete", 0) == 0)
            std::cout << line << std::endl;
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        std::cout << "refused: "
                  << std::regex_replace(Utilities::trim(message.str()),
                                        std::regex("[0-9a-f]{8}"),
                                        "XXXXXXXX")
                  << std::endl;
      }
  }

  bool
  same_statistics_but_wall_time(const std::string &a, const std::string &b)
  {
    const std::regex wall_time_column("^([^,]*,){5}[^,]*");
    const auto       x = read_lines(a), y = read_lines(b);
    if (x.size() != y.size())
      return false;
    for (unsigned int r = 0; r < x.size(); ++r)
      if (std::regex_replace(x[r], wall_time_column, "$1")
          != std::regex_replace(y[r], wall_time_column, "$1"))
        return false;
    return true;
  }
} // namespace



int
main(int argc, char **argv)
{
  // MPI-IO as the program chooses it (mpi_io_choice.h).
  VPContact::prefer_romio_for_mpi_io();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The folders of an earlier run of this test go: it damages them.
  for (const std::string folder : {"full", "part", "none"})
    std::filesystem::remove_all(folder);

  ParameterHandler full;
  set_checkpoint_scene(full, "full", 4);
  run_logged(full, MPI_COMM_WORLD, "full.log");
  ParameterHandler part;
  set_checkpoint_scene(part, "part", 4);
  run_logged(part, MPI_COMM_WORLD, "part.log", "step 6 ");

  // The newest checkpoint loses half of its cell data; a later checkpoint
  // was being written when the run was killed (the program marks the
  // folder as its own before it writes into it).
  const std::string data = "part/checkpoint/mesh_fixed.data";
  std::filesystem::resize_file(data, std::filesystem::file_size(data) / 2);
  std::filesystem::create_directories("part/checkpoint.new");
  std::filesystem::copy_file("part/checkpoint/.vpcontact-checkpoint",
                             "part/checkpoint.new/.vpcontact-checkpoint");
  std::ofstream("part/checkpoint.new/mesh") << "partial";
  resume("part", "", "newest checkpoint truncated");
  std::cout << "statistics.csv equal to the uninterrupted run's (but "
               "wall_time): "
            << (same_statistics_but_wall_time("full/statistics.csv",
                                              "part/statistics.csv") ?
                  "yes" :
                  "NO")
            << std::endl;

  resume("part", "", "the run is complete");
  resume("part",
         "subsection Material\n set Young's modulus = 2000\nend\n"
         "subsection Time\n set End time = 0.48\nend",
         "another Young's modulus");
  resume("part",
         "subsection Time\n set End time = 0.48\nend",
         "a later end time");

  // A byte of the newest p4est file changed, a file of the previous
  // checkpoint lost.
  {
    std::fstream mesh("part/checkpoint/mesh",
                      std::ios::in | std::ios::out | std::ios::binary);
    mesh.seekg(100);
    const char byte = static_cast<char>(mesh.get() ^ 0x5a);
    mesh.seekp(100);
    mesh.put(byte);
  }
  std::filesystem::remove("part/checkpoint.old/mesh.info");
  resume("part",
         "subsection Time\n set End time = 0.56\nend",
         "every checkpoint damaged");

  std::filesystem::create_directories("none");
  resume("none", "", "no checkpoint");
}
