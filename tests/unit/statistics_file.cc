// Checks statistics.csv as a user reads it: the header names the columns
// (at least step,time,cells,dofs, the linear iterations and the wall time),
// there is one row per step, and the columns that depend only on the
// discrete solution are the same on 1 and 2 MPI ranks (the .mpirun=2 output
// is the same file as the serial one). The scene is the elastic bar with an
// 8 x 2 mesh; values are printed with 6 digits, far above the solver
// tolerance 1e-12.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cstdio>
#include <fstream>
#include <iostream>

#include "scene_runner.h"

using namespace VPContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool rank_zero = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  ParameterHandler prm;
  Simulator<2>::declare_parameters(prm);
  prm.parse_input_from_string(R"(
    subsection Geometry
      set Upper corner = 4, 1
      set Subdivisions = 8, 2
    end
    subsection Boundary conditions
      set Clamped boundary ids  =
      set Roller boundary ids   = 0:x, 2:y
      set Traction              = 50*t; 0
    end
    subsection Time
      set Time step = 0.25
    end
    subsection Solver
      set Relative tolerance = 1e-12
    end
    subsection Output
      set Directory    = stats_run
      set Output every = 0
      set Deterministic screen output = true
    end)");
  // The simulator's own screen output goes to a file: this test prints
  // only what it reads back from statistics.csv.
  run_quietly<2>(prm, ".");

  if (rank_zero)
    {
      std::ifstream in("stats_run/statistics.csv");
      std::string   line;
      std::getline(in, line);
      std::cout << "header: " << line << '\n';
      const auto   columns = Utilities::split_string_list(line, ',');
      unsigned int n_rows  = 0;
      while (std::getline(in, line))
        {
          const auto values = Utilities::split_string_list(line, ',');
          AssertThrow(values.size() == columns.size(), ExcInternalError());
          std::cout << "row " << n_rows++ << ':';
          for (unsigned int c = 0; c < columns.size(); ++c)
            if (columns[c] != "wall_time" && columns[c] != "linear_iterations")
              std::printf(" %s=%.6g",
                          columns[c].c_str(),
                          Utilities::string_to_double(values[c]));
          std::cout << std::endl;
        }
      std::cout << "rows: " << n_rows << " (steps 0..4)" << std::endl;
    }
}
