// The --print-parameters listing: every entry with its default, its allowed
// values and its documentation, written as a valid parameter file; and the
// current values as a flat list.
#ifndef vpcontact_parameter_listing_h
#define vpcontact_parameter_listing_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <ostream>
#include <string>

namespace VPContact
{
  /**
   * Write every entry declared in @p prm as `set Name = default`, preceded
   * by comment lines with its documentation and its allowed values.
   * ParameterHandler's own PRM style leaves the allowed values out, so the
   * listing is built from its JSON form, which has them.
   */
  void
  print_parameter_listing(const dealii::ParameterHandler &prm,
                          std::ostream                   &out);

  /**
   * The current value of every entry of @p prm, keyed by its path
   * "Section/Subsection/Entry" (top-level entries by their name alone).
   */
  std::map<std::string, std::string>
  parameter_values(const dealii::ParameterHandler &prm);

  /**
   * The pattern of every entry of @p prm as ParameterHandler describes it
   * ("[Double 0...MAX_DOUBLE (inclusive)]", "[List of <[Double ...]> ...]"),
   * keyed like parameter_values().
   */
  std::map<std::string, std::string>
  parameter_patterns(const dealii::ParameterHandler &prm);
} // namespace VPContact

#endif
