// The --print-parameters listing and the flat list of values, both built from
// ParameterHandler's JSON output.
#include <vpcontact/input/parameter_listing.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <sstream>
#include <string>

namespace VPContact
{
  namespace
  {
    // ParameterHandler stores names with every character that is not a
    // letter or digit written as '_' and two hex digits ("Young_27s_20...").
    std::string
    demangle(const std::string &name)
    {
      std::string out;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size())
          {
            out += static_cast<char>(
              std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += name[i];
      return out;
    }

    // Wrap @p text into comment lines of at most 78 characters.
    void
    print_comment(std::ostream      &out,
                  const std::string &indent,
                  const std::string &text)
    {
      std::istringstream words(text);
      std::string        word, line;
      while (words >> word)
        {
          if (!line.empty()
              && indent.size() + 2 + line.size() + 1 + word.size() > 78)
            {
              out << indent << "# " << line << '\n';
              line.clear();
            }
          line += (line.empty() ? "" : " ") + word;
        }
      if (!line.empty())
        out << indent << "# " << line << '\n';
    }

    void
    print_section(std::ostream                      &out,
                  const boost::property_tree::ptree &tree,
                  const std::string                 &indent)
    {
      // Entries first, then subsections, as in ParameterHandler's own PRM.
      for (const auto &[name, node] : tree)
        if (node.get_optional<std::string>("value"))
          {
            print_comment(out,
                          indent,
                          node.get<std::string>("documentation", ""));
            print_comment(out,
                          indent,
                          "Allowed: "
                            + node.get<std::string>("pattern_description", ""));
            out << indent << "set " << demangle(name) << " = "
                << node.get<std::string>("default_value", "") << "\n\n";
          }
      for (const auto &[name, node] : tree)
        if (!node.get_optional<std::string>("value"))
          {
            out << indent << "subsection " << demangle(name) << '\n';
            print_section(out, node, indent + "  ");
            out << indent << "end\n\n";
          }
    }

    // The field @p key ("value", "pattern_description") of every entry
    // below @p tree, keyed by the entry's path.
    void
    collect_field(const boost::property_tree::ptree  &tree,
                  const std::string                  &prefix,
                  const std::string                  &key,
                  std::map<std::string, std::string> &fields)
    {
      for (const auto &[name, node] : tree)
        if (node.get_optional<std::string>("value"))
          fields[prefix + demangle(name)] = node.get<std::string>(key, "");
        else
          collect_field(node, prefix + demangle(name) + "/", key, fields);
    }

    std::map<std::string, std::string>
    collect_field(const dealii::ParameterHandler &prm, const std::string &key)
    {
      std::stringstream json;
      prm.print_parameters(json, dealii::ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      std::map<std::string, std::string> fields;
      collect_field(tree, "", key, fields);
      return fields;
    }
  } // namespace



  void
  print_parameter_listing(const dealii::ParameterHandler &prm,
                          std::ostream                   &out)
  {
    std::stringstream json;
    prm.print_parameters(json, dealii::ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    print_section(out, tree, "");
  }



  std::map<std::string, std::string>
  parameter_values(const dealii::ParameterHandler &prm)
  {
    return collect_field(prm, "value");
  }



  std::map<std::string, std::string>
  parameter_patterns(const dealii::ParameterHandler &prm)
  {
    return collect_field(prm, "pattern_description");
  }
} // namespace VPContact
