// Input that rank 0 alone reads from the file system and hands to every rank
// (the parameter file, the mesh file), so that all ranks compute from the
// same bytes and stop together, with one message, when it cannot be read.
#ifndef vpcontact_rank_zero_input_h
#define vpcontact_rank_zero_input_h

#include <functional>
#include <mpi.h>
#include <string>

namespace VPContact
{
  /**
   * Call @p read on rank 0 of @p communicator only and return its bytes on
   * every rank. If it throws, every rank throws a dealii::ExcMessage with
   * its message: a file that rank 0 cannot read stops all ranks at once,
   * and a rank whose working directory holds another copy (or none) never
   * reads it. Collective.
   */
  std::string
  read_on_rank_zero(const MPI_Comm                      communicator,
                    const std::function<std::string()> &read);

  /**
   * The bytes of the file @p filename; throws a message that says @p what
   * the file is if it cannot be read to its end.
   */
  std::string
  file_bytes(const std::string &filename, const std::string &what);
} // namespace VPContact

#endif
