// Checks that a run stopped by SIGTERM and resumed from its checkpoint ends
// exactly where an uninterrupted run ends. The scene is the paper scene on an
// 8 x 8 mesh with slip and damage (checkpoint_runner.h), 20 steps, a
// checkpoint every 4 steps. Rank 0 alone runs it uninterrupted, then again
// with SIGTERM raised during step 6, which stops the run at the end of step 6
// with a checkpoint; the run is then resumed on all ranks. With 1 rank the
// resumed run must reproduce the uninterrupted one bit for bit (statistics
// except the wall time, .pvd record, and the fields of the final checkpoint:
// solution, last three increments, stick/slip and damage bound sets, stress
// history at the quadrature points). The 2-rank variant resumes the 1-rank
// checkpoint on 2 ranks; the linear solves then differ at round-off, and
// the results must agree to 1e-8 (the solver tolerance is 1e-12), the
// active sets exactly.
#include <vpcontact/app/mpi_io_choice.h>

#include <deal.II/base/mpi.h>

#include "checkpoint_resume_check.h"

int
main(int argc, char **argv)
{
  // MPI-IO as the program chooses it (mpi_io_choice.h).
  VPContact::prefer_romio_for_mpi_io();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_resume("");
}
