// Checks that a run whose mesh adapts during the run, stopped by SIGTERM
// after an adaptation and resumed from its checkpoint, ends where the
// uninterrupted run ends: the checkpoint scene of checkpoint_resume.cc (the
// paper scene on 8 x 8 cells with slip and damage, 20 steps, a checkpoint
// every 4 steps) with Mesh refinement/Adapt during run every 5 steps (a
// fraction 0.3 of the indicator refined, 0.1 coarsened, at most two levels
// above the coarse mesh). The run is stopped at the end of step 6, after the
// first adaptation; the resumed run adapts after steps 10 and 15 as the
// uninterrupted one does. With 1 rank the statistics (cells and degrees of
// freedom of every step included) and the final checkpoint's fields must be
// identical; on 2 ranks the solves differ at round-off, and the results must
// agree to 1e-8, the meshes and active sets exactly.
#include <vpcontact/app/mpi_io_choice.h>

#include <deal.II/base/mpi.h>

#include "checkpoint_resume_check.h"

int
main(int argc, char **argv)
{
  // MPI-IO as the program chooses it (mpi_io_choice.h).
  VPContact::prefer_romio_for_mpi_io();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_resume(R"(
    subsection Mesh refinement
      set Adapt during run     = true
      set Adapt every          = 5
      set Refinement fraction  = 0.3
      set Coarsening fraction  = 0.1
      set Maximum level        = 2
    end
    subsection Error estimate
      set Every steps = 1
    end)");
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::cout << "adaptations of the uninterrupted run:" << std::endl;
      for (const auto &line : read_lines("full.log"))
        if (line.rfind("  mesh adapted", 0) == 0)
          std::cout << line << std::endl;
    }
}
