// The statistics table on deal.II's TableHandler, and its CSV form.
#include <vpcontact/postprocess/statistics.h>

#include <deal.II/base/exceptions.h>

#include <cstdio>
#include <sstream>
#include <vector>

namespace VPContact
{
  void
  Statistics::start_row()
  {
    // TableHandler pads the columns that the last row left empty with the
    // empty text (every entry here is text).
    start_new_row();
    ++rows;
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
    Assert(rows > 0, dealii::ExcMessage("call start_row() first"));
    // A column that first appears in a later row is empty above it.
    if (columns.find(column) == columns.end())
      {
        declare_column(column);
        columns[column].entries.assign(rows - 1,
                                       dealii::internal::TableEntry(
                                         std::string()));
      }
    TableHandler::add_value(column, text);
  }



  std::string
  Statistics::to_csv() const
  {
    std::ostringstream out;
    for (unsigned int c = 0; c < column_order.size(); ++c)
      out << (c == 0 ? "" : ",") << column_order[c];
    out << '\n';
    for (unsigned int r = 0; r < rows; ++r)
      {
        for (unsigned int c = 0; c < column_order.size(); ++c)
          {
            const auto &entries = columns.at(column_order[c]).entries;
            out << (c == 0 ? "" : ",")
                << (r < entries.size() ? entries[r].get<std::string>() : "");
          }
        out << '\n';
      }
    return out.str();
  }



  unsigned int
  Statistics::n_rows() const
  {
    return rows;
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
    *this = Statistics();
    std::istringstream in(csv);
    std::string        line;
    if (!std::getline(in, line))
      return;
    const std::vector<std::string> header = split(line);
    for (const auto &column : header)
      declare_column(column);
    while (std::getline(in, line))
      {
        const auto cells = split(line);
        AssertThrow(cells.size() <= header.size(),
                    dealii::ExcMessage("A row of the statistics table has "
                                       "more cells than its header."));
        start_row();
        for (unsigned int c = 0; c < cells.size(); ++c)
          if (!cells[c].empty())
            add_text(header[c], cells[c]);
      }
  }
} // namespace VPContact
