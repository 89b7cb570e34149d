// Checks the run-time safeguard against a blown-up stress: with
// Viscoplasticity/Divergence limit = 0.018 (stress above 0.018 E = 18 Pa counts
// as divergence) the elastic bar, whose stress grows by 5 Pa per step,
// stops in step 4 with a message naming the step and the remedy, and the
// output written so far is intact: statistics.csv has the rows of steps 0..3
// and solution.pvd lists the fields written before the stop.
#include <deal.II/base/mpi.h>

#include <fstream>
#include <iostream>
#include <sstream>

#include "scene_runner.h"

using namespace VPContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  Simulator<2>::declare_parameters(prm);
  prm.parse_input(SOURCE_DIR "/../../prm/elastic_bar.prm");
  prm.enter_subsection("Viscoplasticity");
  prm.set("Divergence limit", "0.018");
  prm.leave_subsection();
  prm.enter_subsection("Output");
  prm.set("Directory", "run");
  prm.set("Output every", "1");
  prm.leave_subsection();

  try
    {
      run_quietly<2>(prm, SOURCE_DIR "/../../prm");
      std::cout << "the run did NOT stop" << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      std::cout << "stopped: ";
      e.print_info(std::cout);
    }

  std::ifstream statistics("run/statistics.csv");
  std::string   line;
  unsigned int  n_lines = 0;
  while (std::getline(statistics, line))
    ++n_lines;
  std::cout << "statistics.csv: header + " << n_lines - 1 << " rows"
            << std::endl;

  std::ifstream     pvd("run/solution.pvd");
  std::stringstream content;
  content << pvd.rdbuf();
  unsigned int n_datasets = 0;
  for (std::size_t at = 0;
       (at = content.str().find("<DataSet", at)) != std::string::npos;
       ++at)
    ++n_datasets;
  std::cout << "solution.pvd: " << n_datasets << " time steps, ends with "
            << (content.str().find("</VTKFile>") != std::string::npos ?
                  "</VTKFile> (complete)" :
                  "no closing tag (truncated)")
            << std::endl;
}
