// Which of Open MPI's MPI-IO implementations writes and reads the
// checkpoints: ROMIO where the Open MPI build has it (mpi_io_choice.cc says
// why).
#ifndef vpcontact_mpi_io_choice_h
#define vpcontact_mpi_io_choice_h

namespace VPContact
{
  /**
   * Ask Open MPI to open files with ROMIO rather than with OMPIO: raise the
   * priority of its ROMIO components (io_romio321 of Open MPI 4,
   * io_romio341 of Open MPI 5) above OMPIO's 30, in the environment that
   * MPI_Init reads. Call before MPI starts, in every process (under mpirun
   * each rank does it alone).
   *
   * A user's own choice stands: with OMPI_MCA_io set (the list of
   * components; mpirun --mca io sets it too), or a priority already in the
   * environment, nothing is changed. An Open MPI without ROMIO, and other
   * MPI libraries, do not read these variables.
   */
  void
  prefer_romio_for_mpi_io();
} // namespace VPContact

#endif
