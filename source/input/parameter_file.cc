// Reading a scene's parameter file: the file and its includes checked before
// ParameterHandler reads them, and the range of the numbers it holds.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parameter_file.h>
#include <vpcontact/input/parameter_listing.h>
#include <vpcontact/input/rank_zero_input.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace VPContact
{
  namespace
  {
    namespace fs = std::filesystem;

    // Deeper include chains than this are not a scene a user wrote by hand;
    // the limit also bounds the recursion below.
    constexpr unsigned int max_include_depth = 32;

    // Throw unless @p path names a regular file that can be opened. @p what
    // names the file and says how it came in ("The parameter file 'a.prm'",
    // "The file 'b.prm' included in line 3 of a.prm").
    void
    check_readable_file(const std::string &path, const std::string &what)
    {
      std::error_code error;
      const auto      status = fs::status(path, error);
      // A loop of symbolic links, for one, is an error other than "no such
      // file".
      AssertThrow(!error || error == std::errc::no_such_file_or_directory,
                  dealii::ExcMessage(what + " cannot be examined ("
                                     + error.message() + "). Check the path."));
      AssertThrow(fs::exists(status),
                  dealii::ExcMessage(what
                                     + " does not exist. Check the path."));
      AssertThrow(fs::is_regular_file(status),
                  dealii::ExcMessage(
                    what
                    + " is not a regular file (a folder or a device). Give "
                      "the path of a parameter file (.prm)."));
      AssertThrow(std::ifstream(path).good(),
                  dealii::ExcMessage(what
                                     + " cannot be read (no permission?)."));
    }

    // The file named by an "include" line, or an empty string if the line is
    // not one. ParameterHandler accepts "include" and "INCLUDE" followed by
    // the rest of the line as the file name.
    std::string
    included_file(const std::string &line)
    {
      std::size_t start = line.find_first_not_of(" \t");
      if (start == std::string::npos)
        return "";
      const std::string rest = line.substr(start);
      if (rest.rfind("include ", 0) != 0 && rest.rfind("INCLUDE ", 0) != 0)
        return "";
      std::string name = rest.substr(8);
      name.erase(0, name.find_first_not_of(" \t"));
      while (
        !name.empty()
        && (name.back() == ' ' || name.back() == '\t' || name.back() == '\r'))
        name.pop_back();
      return name;
    }

    // Whether @p line is valid UTF-8: the parameters are handled as JSON
    // (the listing, the checkpoint's record), which holds only UTF-8.
    bool
    is_utf8(const std::string &line)
    {
      for (std::size_t i = 0; i < line.size(); ++i)
        {
          const auto         c = static_cast<unsigned char>(line[i]);
          const unsigned int n = (c < 0x80)           ? 0 :
                                 ((c & 0xE0) == 0xC0) ? 1 :
                                 ((c & 0xF0) == 0xE0) ? 2 :
                                 ((c & 0xF8) == 0xF0) ? 3 :
                                                        4;
          if (n == 4 || i + n >= line.size())
            return false;
          // The n bytes that continue the character are 10xxxxxx.
          for (unsigned int k = 0; k < n; ++k)
            if ((static_cast<unsigned char>(line[++i]) & 0xC0) != 0x80)
              return false;
        }
      return true;
    }

    // Append the lines of @p path to @p file, with every "include" line
    // replaced by the lines of the file it names (a relative name taken
    // from the folder of the file that includes it), depth first. @p chain
    // holds the files from the top one down to @p path (canonical names),
    // so that a file that includes one of its own includers is refused
    // before the recursion runs away.
    void
    append_with_includes(const std::string        &path,
                         std::vector<std::string> &chain,
                         ParameterFile            &file)
    {
      const std::string canonical = fs::weakly_canonical(path).string();
      for (const auto &f : chain)
        if (f == canonical)
          {
            std::string cycle;
            for (const auto &g : chain)
              cycle += g + " -> ";
            AssertThrow(false,
                        dealii::ExcMessage(
                          "The parameter files include each other in a "
                          "cycle: "
                          + cycle + canonical
                          + ". Remove the include that closes it."));
          }
      AssertThrow(chain.size() < max_include_depth,
                  dealii::ExcMessage("The includes of " + chain.front()
                                     + " nest deeper than "
                                     + std::to_string(max_include_depth)
                                     + " files. Flatten them."));
      chain.push_back(canonical);
      const fs::path folder = fs::path(path).parent_path();
      std::ifstream  in(path);
      std::string    line;
      for (unsigned int n = 1; std::getline(in, line); ++n)
        {
          // Editors on Windows may start a file with a byte order mark.
          if (n == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
            line.erase(0, 3);
          AssertThrow(is_utf8(line),
                      dealii::ExcMessage(
                        "Line " + std::to_string(n) + " of " + path
                        + " is not UTF-8 text. Save the parameter file as "
                          "UTF-8."));
          const std::string name = included_file(line);
          if (name.empty())
            {
              file.text += line + '\n';
              file.origins.emplace_back(path, n);
              continue;
            }
          const std::string included
            = fs::path(name).is_relative() ? (folder / name).string() : name;
          check_readable_file(included,
                              "The file '" + name + "' included in line "
                                + std::to_string(n) + " of " + path);
          append_with_includes(included, chain, file);
        }
      chain.pop_back();
    }
  } // namespace



  ParameterFile
  read_parameter_file(const std::string &filename)
  {
    check_readable_file(filename, "The parameter file '" + filename + "'");
    ParameterFile            file;
    std::vector<std::string> chain;
    append_with_includes(filename, chain, file);
    return file;
  }



  ParameterFile
  read_parameter_file(const std::string &filename, const MPI_Comm communicator)
  {
    ParameterFile file;
    file.text = read_on_rank_zero(communicator, [&]() {
      file = read_parameter_file(filename);
      return file.text;
    });
    file.origins
      = dealii::Utilities::MPI::broadcast(communicator, file.origins, 0);
    return file;
  }



  std::string
  ParameterFile::locate(const std::string &message) const
  {
    // ParameterHandler writes "Line <N> of file <F>" with N the line of the
    // text it was given.
    static const std::regex place("Line <([0-9]+)> of file <[^>]*>");
    std::smatch             match;
    if (!std::regex_search(message, match, place))
      return message;
    const unsigned long n = std::stoul(match[1].str());
    if (n == 0 || n > origins.size())
      return message;
    const auto &[path, line] = origins[n - 1];
    return match.prefix().str() + "Line <" + std::to_string(line)
           + "> of file <" + path + ">" + match.suffix().str();
  }



  namespace
  {
    // The numbers in an entry's value: every word between the separators
    // of lists and maps (',', ';', ':', spaces) that reads as a whole as a
    // real number. Words of expressions ("2*x") are not numbers.
    std::vector<std::pair<std::string, double>>
    numbers_in(const std::string &value)
    {
      std::vector<std::pair<std::string, double>> numbers;
      std::string                                 word;
      const auto                                  take_word = [&]() {
        if (!word.empty())
          {
            char *end = nullptr;
            errno     = 0;
            const double x = std::strtod(word.c_str(), &end);
            // strtod reads "inf", "nan" and overflows to HUGE_VAL with
            // ERANGE: all are numbers this program must refuse.
            if (end != word.c_str() && *end == '\0')
              numbers.emplace_back(word,
                                   errno == ERANGE && std::abs(x) > 1 ?
                                                                      HUGE_VAL :
                                                                      x);
          }
        word.clear();
      };
      for (const char c : value)
        if (c == ',' || c == ';' || c == ':' || c == ' ' || c == '\t')
          take_word();
        else
          word += c;
      take_word();
      return numbers;
    }
  } // namespace



  void
  check_number_ranges(const dealii::ParameterHandler &prm)
  {
    // Only entries whose pattern holds numbers: a folder named "1e999" is
    // a name, not a number.
    const auto patterns = parameter_patterns(prm);
    for (const auto &[entry, value] : parameter_values(prm))
      for (const auto &[word, x] : numbers_in(value))
        {
          const std::string &pattern = patterns.at(entry);
          if (pattern.find("Double") == std::string::npos
              && pattern.find("Integer") == std::string::npos)
            break;
          const double magnitude = std::abs(x);
          VPContactCheckParameter(
            std::isfinite(x)
              && (magnitude == 0
                  || (magnitude >= smallest_magnitude
                      && magnitude <= largest_magnitude)),
            entry,
            value,
            "the number " + word
              + " is not one this program can compute with: a number in a "
                "parameter file is 0 or has a magnitude between 1e-100 and "
                "1e100 (so that products and squares of the inputs stay "
                "finite in double precision). Rescale the units of the "
                "scene.");
        }
  }
} // namespace VPContact
