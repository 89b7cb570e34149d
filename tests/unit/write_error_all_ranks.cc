// A write that fails on one rank in the middle of a run must stop every rank
// with its message: rank 0 alone writes statistics.csv and the reference
// snapshots, and if only rank 0 stopped, the other ranks would wait for it in
// their next collective call for ever (the test would then time out). The
// same for the .vtu piece of the last rank, which is written in the
// background: its failure is found when the output is finished, and must
// reach every rank. Each write is made to fail with a folder in the way of
// its temporary file (as root, permissions would not stop it). Serial and on
// 2 ranks.
#include <vpcontact/postprocess/output_writer.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "scene_runner.h"

using namespace VPContact;

namespace
{
  // Run elastic_bar.prm into @p folder with @p in_the_way made a folder
  // first, and print whether every rank stopped with a message naming it.
  void
  check_stops_every_rank(const std::string &folder,
                         const std::string &in_the_way,
                         const bool         write_snapshots)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::filesystem::remove_all(folder);
        std::filesystem::create_directories(folder + "/" + in_the_way);
        // The folder of an earlier run of the program, which it may write
        // into again.
        write_folder_marker(folder, output_folder_marker);
      }
    MPI_Barrier(comm);

    ParameterHandler prm;
    Simulator<2>::declare_parameters(prm);
    prm.parse_input(SOURCE_DIR "/../../prm/elastic_bar.prm");
    set_entry(prm, "Output", "Directory", folder);
    if (write_snapshots)
      {
        set_entry(prm, "Reference solution", "Write snapshots", "true");
        set_entry(prm, "Reference solution", "Snapshot interval", "0.1");
      }

    std::string message;
    try
      {
        run_quietly<2>(prm, SOURCE_DIR "/../../prm");
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        message = info.str();
      }
    const std::string  file = folder + "/" + in_the_way;
    const unsigned int stopped_here
      = message.find("Cannot write the file " + file) != std::string::npos;
    const unsigned int n_stopped = Utilities::MPI::sum(stopped_here, comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::cout << "every rank stopped with the message naming " << file << ": "
                << (n_stopped == Utilities::MPI::n_mpi_processes(comm) ? "yes" :
                                                                         "no")
                << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_stops_every_rank("run", "statistics.csv.tmp", false);
  check_stops_every_rank("run_reference",
                         "reference/snapshot-00000.bin.tmp",
                         true);
  const unsigned int last_rank
    = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) - 1;
  check_stops_every_rank("run_fields",
                         "solution_00005." + std::to_string(last_rank)
                           + ".vtu.tmp",
                         false);
}
