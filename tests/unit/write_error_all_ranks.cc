// A write that fails on rank 0 in the middle of a run must stop every rank
// with its message: rank 0 alone writes statistics.csv, and if only rank 0
// stopped, the other ranks would wait for it in their next collective call
// for ever (the test would then time out). The write is made to fail with a
// folder in the way of the temporary file statistics.csv.tmp (as root,
// permissions would not stop it). Serial and on 2 ranks.
#include <deal.II/base/mpi.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "scene_runner.h"

using namespace VPContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::filesystem::remove_all("run");
      std::filesystem::create_directories("run/statistics.csv.tmp");
    }
  MPI_Barrier(comm);

  ParameterHandler prm;
  Simulator<2>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/elastic_bar.prm");
  set_entry(prm, "Output", "Directory", "run");

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
  const bool names_file
    = message.find("Cannot write the file run/statistics.csv.tmp")
      != std::string::npos;
  const unsigned int stopped_here = names_file ? 1 : 0;
  const unsigned int n_stopped    = Utilities::MPI::sum(stopped_here, comm);
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    std::cout << "every rank stopped with the message naming "
                 "run/statistics.csv.tmp: "
              << (n_stopped == Utilities::MPI::n_mpi_processes(comm) ? "yes" :
                                                                       "no")
              << std::endl;
}
