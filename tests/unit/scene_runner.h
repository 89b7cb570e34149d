// Helpers for the unit tests that run the simulator on a scene: run it with
// its screen output kept out of the test's output, and read statistics.csv
// back as rows of named values.
#ifndef vpcontact_tests_scene_runner_h
#define vpcontact_tests_scene_runner_h

#include <vpcontact/simulator/simulator.h>

#include <deal.II/base/utilities.h>

#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace VPContact
{
  /// Run the scene of @p prm; its screen output goes to screen.log.
  template <int dim>
  void
  run_quietly(ParameterHandler &prm, const std::string &parameter_directory)
  {
    std::ofstream   log("screen.log");
    std::streambuf *old = std::cout.rdbuf(log.rdbuf());
    try
      {
        Simulator<dim> simulator(prm, parameter_directory, MPI_COMM_WORLD);
        simulator.run();
      }
    catch (...)
      {
        std::cout.rdbuf(old);
        throw;
      }
    std::cout.rdbuf(old);
  }

  /// Set "Section/Entry" (one level of section) to @p value.
  inline void
  set_entry(ParameterHandler  &prm,
            const std::string &section,
            const std::string &entry,
            const std::string &value)
  {
    prm.enter_subsection(section);
    prm.set(entry, value);
    prm.leave_subsection();
  }

  /// The rows of a statistics.csv or convergence.csv file (empty cells,
  /// trailing ones included, read as 0).
  inline std::vector<std::map<std::string, double>>
  read_statistics(const std::string &filename)
  {
    std::ifstream in(filename);
    std::string   line;
    std::getline(in, line);
    const auto columns = Utilities::split_string_list(line, ',');
    std::vector<std::map<std::string, double>> rows;
    while (std::getline(in, line))
      {
        const auto values = Utilities::split_string_list(line, ',');
        rows.emplace_back();
        for (unsigned int c = 0; c < columns.size(); ++c)
          rows.back()[columns[c]] = (c >= values.size() || values[c].empty()) ?
                                      0. :
                                      Utilities::string_to_double(values[c]);
      }
    return rows;
  }
} // namespace VPContact

#endif
