// The statistics table and its CSV form.
#include <vpcontact/statistics.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace VPContact
{
  void
  Statistics::start_row()
  {
    rows.emplace_back();
  }



  void
  Statistics::add_value(const std::string &column, const double value)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.10g", value);
    add_text(column, buffer);
  }



  void
  Statistics::add_value(const std::string       &column,
                        const unsigned long long value)
  {
    add_text(column, std::to_string(value));
  }



  void
  Statistics::add_value(const std::string &column, const unsigned int value)
  {
    add_text(column, std::to_string(value));
  }



  void
  Statistics::add_text(const std::string &column, const std::string &text)
  {
    Assert(!rows.empty(), dealii::ExcMessage("call start_row() first"));
    if (std::find(columns.begin(), columns.end(), column) == columns.end())
      columns.push_back(column);
    rows.back()[column] = text;
  }



  std::string
  Statistics::to_csv() const
  {
    std::ostringstream out;
    for (unsigned int c = 0; c < columns.size(); ++c)
      out << (c == 0 ? "" : ",") << columns[c];
    out << '\n';
    for (const auto &row : rows)
      {
        for (unsigned int c = 0; c < columns.size(); ++c)
          {
            const auto entry = row.find(columns[c]);
            out << (c == 0 ? "" : ",")
                << (entry == row.end() ? "" : entry->second);
          }
        out << '\n';
      }
    return out.str();
  }



  unsigned int
  Statistics::n_rows() const
  {
    return rows.size();
  }



  void
  Statistics::read_csv(const std::string &csv)
  {
    // The cells are the texts to_csv() wrote, kept as they are, so that the
    // table writes back to the same text; an empty cell is no value.
    const auto split = [](const std::string &line) {
      std::vector<std::string> cells(1);
      for (const char c : line)
        if (c == ',')
          cells.emplace_back();
        else
          cells.back() += c;
      return cells;
    };
    std::istringstream in(csv);
    std::string        line;
    columns.clear();
    rows.clear();
    if (!std::getline(in, line))
      return;
    columns = split(line);
    while (std::getline(in, line))
      {
        const auto cells = split(line);
        AssertThrow(cells.size() <= columns.size(),
                    dealii::ExcMessage("A row of the statistics table has "
                                       "more cells than its header."));
        rows.emplace_back();
        for (unsigned int c = 0; c < cells.size(); ++c)
          if (!cells[c].empty())
            rows.back()[columns[c]] = cells[c];
      }
  }
} // namespace VPContact
