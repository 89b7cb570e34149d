// How input errors are worded: every message names the parameter (section and
// entry) or the file, the offending value, and what to do about it.
#ifndef vpcontact_input_error_h
#define vpcontact_input_error_h

#include <deal.II/base/exceptions.h>

#include <cstdio>
#include <exception>
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

  /// @p value printed by the printf @p pattern of one double, as the
  /// screen lines print their figures.
  inline std::string
  printf_text(const char *pattern, const double value)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), pattern, value);
    return buffer;
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

  /**
   * What went wrong, in words, for an exception from anywhere: for deal.II's
   * exceptions only their message (what() would add the assertion's source
   * location and a stack trace, which tell a user nothing), else what().
   */
  inline std::string
  error_message(const std::exception &e)
  {
    const auto *deal = dynamic_cast<const dealii::ExceptionBase *>(&e);
    if (deal == nullptr)
      return e.what();
    std::ostringstream info;
    deal->print_info(info);
    std::string message = info.str();
    const auto  first   = message.find_first_not_of(" \n");
    const auto  last    = message.find_last_not_of(" \n");
    message
      = (first == std::string::npos ? std::string() :
                                      message.substr(first, last - first + 1));
    // Exceptions declared without a message print "(none)".
    if (message.empty() || message == "(none)")
      message = std::string("deal.II reported ") + deal->get_exc_name();
    return message;
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
