// Input read by rank 0 alone and handed to every rank.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/rank_zero_input.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <cstdint>
#include <fstream>
#include <sstream>

namespace VPContact
{
  std::string
  read_on_rank_zero(const MPI_Comm                      communicator,
                    const std::function<std::string()> &read)
  {
    std::string bytes, problem;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          bytes = read();
        }
      catch (const std::exception &e)
        {
          problem = error_message(e);
          // A message must not be empty: it is what tells the ranks apart
          // from success.
          if (problem.empty())
            problem = "the input could not be read.";
        }
    problem = dealii::Utilities::MPI::broadcast(communicator, problem, 0);
    AssertThrow(problem.empty(), dealii::ExcMessage(problem));
    // The bytes go as a plain buffer (in pieces of at most 2^31 bytes,
    // which broadcast() cuts): a mesh file may be large.
    const std::uint64_t size
      = dealii::Utilities::MPI::broadcast(communicator,
                                          static_cast<std::uint64_t>(
                                            bytes.size()),
                                          0);
    bytes.resize(size);
    dealii::Utilities::MPI::broadcast(bytes.data(), size, 0, communicator);
    return bytes;
  }



  std::string
  file_bytes(const std::string &filename, const std::string &what)
  {
    std::ifstream in(filename, std::ios::binary);
    AssertThrow(in, dealii::ExcMessage(what + " cannot be opened."));
    std::ostringstream bytes;
    bytes << in.rdbuf();
    AssertThrow(!in.bad(),
                dealii::ExcMessage(what + " cannot be read to its end."));
    return bytes.str();
  }
} // namespace VPContact
