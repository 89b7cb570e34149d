// Reading a scene's parameter file safely: the file and every file it
// includes are checked before deal.II's ParameterHandler sees them, and the
// numbers it holds are checked against what double precision can carry.
#ifndef vpcontact_parameter_file_h
#define vpcontact_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace VPContact
{
  /**
   * The text of the parameter file @p filename, ready for
   * ParameterHandler::parse_input(). Throws a message naming the file if
   * it, or a file it includes (at any depth), is not a readable regular
   * file, or if the includes form a cycle (deal.II would recurse until the
   * stack overflows).
   *
   * The file name of every "include" statement of @p filename is made
   * relative to the file's own folder (deal.II takes it relative to the
   * working directory), so that a scene can include another scene next to
   * it wherever the program runs. Files included from included files are
   * opened by deal.II as written, and checked here the same way.
   */
  std::string
  read_parameter_file(const std::string &filename);

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
