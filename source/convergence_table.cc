// The convergence table: rows, observed orders, CSV and screen formats.
#include <vpcontact/convergence_table.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>

namespace VPContact
{
  namespace
  {
    using Select = std::function<double(const ConvergenceTable::Row &)>;

    // The error columns: name and how to read it from a row.
    std::vector<std::pair<std::string, Select>>
    error_columns()
    {
      using Row = ConvergenceTable::Row;
      return {
        {"error_u", [](const Row &r) { return r.max_error.displacement; }},
        {"error_stress", [](const Row &r) { return r.max_error.stress; }},
        {"error_damage", [](const Row &r) { return r.max_error.damage; }},
        {"error_sum", [](const Row &r) { return r.max_error_sum; }},
        {"final_error_u",
         [](const Row &r) { return r.final_error.displacement; }},
        {"final_error_stress",
         [](const Row &r) { return r.final_error.stress; }},
        {"final_error_damage",
         [](const Row &r) { return r.final_error.damage; }},
        {"final_error_sum", [](const Row &r) { return r.final_error.sum(); }}};
    }

    std::string
    format(const char *pattern, const double value)
    {
      if (std::isnan(value))
        return "";
      char buffer[64];
      std::snprintf(buffer, sizeof(buffer), pattern, value);
      return buffer;
    }
  } // namespace



  double
  observed_order(const double e_prev,
                 const double e,
                 const double h_prev,
                 const double h)
  {
    if (!(e_prev > 0 && e > 0 && h_prev > 0 && h > 0)
        || std::abs(std::log(h_prev / h)) < 1e-12)
      return std::numeric_limits<double>::quiet_NaN();
    return std::log(e_prev / e) / std::log(h_prev / h);
  }



  void
  ConvergenceTable::add_row(const Row &row)
  {
    table.push_back(row);
  }



  const std::vector<ConvergenceTable::Row> &
  ConvergenceTable::rows() const
  {
    return table;
  }



  std::string
  ConvergenceTable::to_csv() const
  {
    std::ostringstream csv;
    csv << "cycle,cells,dofs,h,k,steps,wall_time,cumulative_wall_time,"
           "compared_times";
    const auto columns = error_columns();
    for (const auto &column : columns)
      csv << ',' << column.first << ',' << column.first << "_order";
    csv << '\n';
    for (unsigned int i = 0; i < table.size(); ++i)
      {
        const Row &r = table[i];
        csv << r.cycle << ',' << r.cells << ',' << r.dofs << ','
            << format("%.10g", r.h) << ',' << format("%.10g", r.k) << ','
            << r.steps << ',' << format("%.4f", r.wall_time) << ','
            << format("%.4f", r.cumulative_wall_time) << ','
            << r.compared_times;
        for (const auto &column : columns)
          {
            if (!r.has_errors)
              {
                csv << ",,";
                continue;
              }
            const double e = column.second(r);
            csv << ',' << format("%.10g", e) << ',';
            if (i > 0 && table[i - 1].has_errors)
              csv << format("%.4f",
                            observed_order(column.second(table[i - 1]),
                                           e,
                                           table[i - 1].h,
                                           r.h));
          }
        csv << '\n';
      }
    return csv.str();
  }



  std::string
  ConvergenceTable::to_text(const bool with_times) const
  {
    // The errors are the largest over the common times (Theorem 2's max_n);
    // the final-time errors are in the CSV.
    std::ostringstream text;
    text << "cycle    cells     dofs         h         k  steps"
         << (with_times ? "   time [s]" : "")
         << "   ||eps(e_u)|| order    ||e_sigma|| order     ||e_zeta|| "
            "order            sum order\n";
    const auto columns = error_columns();
    for (unsigned int i = 0; i < table.size(); ++i)
      {
        const Row &r = table[i];
        char       head[128];
        std::snprintf(head,
                      sizeof(head),
                      "%5u %8llu %8llu %9.3e %9.3e %6u",
                      r.cycle,
                      r.cells,
                      r.dofs,
                      r.h,
                      r.k,
                      r.steps);
        text << head;
        if (with_times)
          text << format(" %10.3f", r.wall_time);
        for (unsigned int c = 0; c < 4; ++c)
          {
            if (!r.has_errors)
              break;
            const double e = columns[c].second(r);
            const double order
              = (i > 0 && table[i - 1].has_errors) ?
                  observed_order(columns[c].second(table[i - 1]),
                                 e,
                                 table[i - 1].h,
                                 r.h) :
                  std::numeric_limits<double>::quiet_NaN();
            char cell[64];
            std::snprintf(cell, sizeof(cell), " %14.6e", e);
            text << cell;
            std::snprintf(cell,
                          sizeof(cell),
                          " %6s",
                          format("%.2f", order).c_str());
            text << cell;
          }
        text << '\n';
      }
    return text.str();
  }
} // namespace VPContact
