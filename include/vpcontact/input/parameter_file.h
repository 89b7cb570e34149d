// Reading a scene's parameter file safely: the file and every file it
// includes are checked before deal.II's ParameterHandler sees them, and the
// numbers it holds are checked against what double precision can carry.
#ifndef vpcontact_parameter_file_h
#define vpcontact_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  /**
   * A parameter file with its includes written out: the text that
   * ParameterHandler::parse_input() reads, and for every line of it the
   * file and line it came from.
   */
  struct ParameterFile
  {
    std::string                                       text;
    std::vector<std::pair<std::string, unsigned int>> origins;

    /**
     * @p message (of ParameterHandler, about a line of text) with the line
     * number of the text replaced by the file and line it came from.
     */
    std::string
    locate(const std::string &message) const;
  };

  /**
   * The parameter file @p filename with every "include" statement replaced
   * by the file it names, at any depth; a relative name is taken from the
   * folder of the file that holds the include (deal.II would take it from
   * the working directory). Throws a message naming the file if it, or a
   * file it includes, is not a readable regular file, or if the includes
   * form a cycle (deal.II would recurse until the stack overflows).
   */
  ParameterFile
  read_parameter_file(const std::string &filename);

  /**
   * The same, read by rank 0 of @p communicator alone: every rank gets its
   * text (and the origins of its lines), so that all ranks run the same
   * scene even where their working directories hold different copies of
   * the file or none, and all stop together with rank 0's message when it
   * cannot read it. Collective.
   */
  ParameterFile
  read_parameter_file(const std::string &filename, const MPI_Comm communicator);

  /**
   * The magnitudes this program accepts for a real number in a parameter
   * file: 0, or between smallest_magnitude and largest_magnitude. Within
   * these, products of a few inputs and their squares (energies, norms)
   * stay finite and normalized in double precision; outside them, a run
   * would end in overflow or in numbers that have lost their digits.
   */
  constexpr double largest_magnitude  = 1e100;
  constexpr double smallest_magnitude = 1e-100;

  /**
   * Throw a message naming the entry if a number in any entry of @p prm
   * (a real value, or an element of a list or map of them) is not finite or
   * has a magnitude outside [smallest_magnitude, largest_magnitude] (0 is
   * accepted). Numbers inside expressions are not seen here: what they
   * evaluate to is checked while the run computes.
   */
  void
  check_number_ranges(const dealii::ParameterHandler &prm);
} // namespace VPContact

#endif
