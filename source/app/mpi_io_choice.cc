// Which of Open MPI's MPI-IO implementations writes and reads the
// checkpoints: ROMIO where the Open MPI build has it, rather than OMPIO.
//
// Why: OMPIO opens every file with a shared file pointer, and on one node
// it guards that pointer with a POSIX named semaphore,
// /dev/shm/sem.OMPIO_<file name>. The name holds only the file's name
// without its folder, so every process of the machine that opens a file of
// that name shares it: each checkpoint's "mesh" and "mesh_fixed.data". A
// process that dies while it holds the semaphore (between OMPIO's sem_wait
// and sem_post) leaves it held, and every later checkpoint of any run on
// that machine then waits for ever in MPI_File_open, until the semaphore is
// removed by hand. Nothing in the checkpoints needs a shared file pointer
// (p4est and deal.II read and write at explicit offsets), and ROMIO makes
// one only when a shared-pointer operation asks for it.
// tests/mpi_io/run.sh holds such a semaphore and checks that runs with
// checkpoints still finish.
#include <vpcontact/app/mpi_io_choice.h>

#include <cstdlib>

namespace VPContact
{
  void
  prefer_romio_for_mpi_io()
  {
    if (std::getenv("OMPI_MCA_io") != nullptr)
      return;
    // Above OMPIO's default priority of 30; setenv(..., 0) keeps a value
    // the user set.
    for (const char *name :
         {"OMPI_MCA_io_romio321_priority", "OMPI_MCA_io_romio341_priority"})
      setenv(name, "40", 0);
  }
} // namespace VPContact
