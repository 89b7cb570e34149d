// How input errors are worded: every message names the parameter (section and
// entry) or the file, the offending value, and what to do about it.
#ifndef vpcontact_input_error_h
#define vpcontact_input_error_h

#include <deal.II/base/exceptions.h>

#include <sstream>
#include <string>

namespace VPContact
{
  /**
   * A value as the user would have typed it: shortest round-trip-ish form
   * with up to 12 significant digits, no trailing zeros.
   */
  template <typename T>
  std::string
  to_text(const T &value)
  {
    std::ostringstream s;
    s.precision(12);
    s << value;
    return s.str();
  }

  /**
   * The message for a parameter whose value cannot be used:
   * "Section/Entry = value: problem" followed by the remedy.
   */
  inline std::string
  parameter_message(const std::string &section_and_entry,
                    const std::string &value,
                    const std::string &problem_and_remedy)
  {
    return section_and_entry + " = " + value + ": " + problem_and_remedy;
  }
} // namespace VPContact

/**
 * Throw a dealii::ExcMessage naming a parameter, unless @p cond holds. Used
 * for user input: active in release builds (it is AssertThrow).
 */
#define VPContactCheckParameter(cond, section_and_entry, value, remedy) \
  AssertThrow(cond,                                                     \
              dealii::ExcMessage(                                       \
                VPContact::parameter_message(section_and_entry,         \
                                             VPContact::to_text(value), \
                                             remedy)))

#endif
