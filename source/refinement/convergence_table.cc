// The convergence table: rows, observed orders (by deal.II's
// ConvergenceTable), CSV and screen formats.
#include <vpcontact/refinement/convergence_table.h>

#include <deal.II/base/convergence_table.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>
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



    // deal.II's ConvergenceTable, for its rates: with the reference column
    // 1/h and dim = 1, reduction_rate_log2 is log(e_prev/e) / log(h_prev/h).
    class RateTable : public dealii::ConvergenceTable
    {
    public:
      // The orders of @p errors against the mesh sizes @p h, row by row: NaN
      // in the first row and where the order is not finite (an error of
      // zero, or the same mesh twice).
      std::vector<double>
      orders(const std::vector<double> &h, const std::vector<double> &errors)
      {
        for (unsigned int i = 0; i < h.size(); ++i)
          {
            add_value("1/h", 1. / h[i]);
            add_value("e", errors[i]);
          }
        const std::set<std::string> before = keys();
        evaluate_convergence_rates("e", "1/h", reduction_rate_log2, 1);
        std::vector<double> result(h.size(),
                                   std::numeric_limits<double>::quiet_NaN());
        for (const auto &[key, column] : columns)
          if (before.count(key) == 0)
            for (unsigned int i = 1; i < column.entries.size(); ++i)
              if (std::isfinite(column.entries[i].get_numeric_value()))
                result[i] = column.entries[i].get_numeric_value();
        return result;
      }

    private:
      std::set<std::string>
      keys() const
      {
        std::set<std::string> result;
        for (const auto &column : columns)
          result.insert(column.first);
        return result;
      }
    };



    // The orders of the error column @p select over the rows of @p table.
    std::vector<double>
    orders_of(const std::vector<ConvergenceTable::Row> &table,
              const Select                             &select)
    {
      std::vector<double> h, errors;
      for (const auto &row : table)
        {
          h.push_back(row.h);
          errors.push_back(select(row));
        }
      return RateTable().orders(h, errors);
    }
  } // namespace



  double
  ConvergenceTable::Row::effectivity() const
  {
    return (has_errors && has_estimate && max_error_sum > 0) ?
             estimate.sum() / max_error_sum :
             std::numeric_limits<double>::quiet_NaN();
  }



  // The estimate columns of the CSV, after the errors: the estimate, its
  // order, its two parts (each the largest over the steps) and the
  // effectivity index.
  static std::string
  estimate_csv_header()
  {
    return ",estimate,estimate_order,estimate_space,estimate_time,"
           "effectivity";
  }



  // The estimate columns of the screen table for @p row: the estimate, its
  // @p order and the effectivity index (after blank error columns where the
  // row has no errors).
  static std::string
  estimate_text(const ConvergenceTable::Row &row, const double order)
  {
    char cell[128];
    std::snprintf(cell,
                  sizeof(cell),
                  " %14.6e %6s %6s",
                  row.estimate.sum(),
                  format("%.2f", order).c_str(),
                  format("%.2f", row.effectivity()).c_str());
    return (row.has_errors ? "" : std::string(4 * 22, ' ')) + cell;
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
    const auto                       columns = error_columns();
    std::vector<std::vector<double>> orders;
    for (const auto &column : columns)
      {
        csv << ',' << column.first << ',' << column.first << "_order";
        orders.push_back(orders_of(table, column.second));
      }
    const std::vector<double> estimate_orders
      = orders_of(table, [](const Row &r) { return r.estimate.sum(); });
    csv << estimate_csv_header() << '\n';
    for (unsigned int i = 0; i < table.size(); ++i)
      {
        const Row &r = table[i];
        csv << r.cycle << ',' << r.cells << ',' << r.dofs << ','
            << format("%.10g", r.h) << ',' << format("%.10g", r.k) << ','
            << r.steps << ',' << format("%.4f", r.wall_time) << ','
            << format("%.4f", r.cumulative_wall_time) << ','
            << r.compared_times;
        for (unsigned int c = 0; c < columns.size(); ++c)
          if (r.has_errors)
            csv << ',' << format("%.10g", columns[c].second(r)) << ','
                << (i > 0 && table[i - 1].has_errors ?
                      format("%.4f", orders[c][i]) :
                      "");
          else
            csv << ",,";
        if (r.has_estimate)
          csv << ',' << format("%.10g", r.estimate.sum()) << ','
              << (i > 0 && table[i - 1].has_estimate ?
                    format("%.4f", estimate_orders[i]) :
                    "")
              << ',' << format("%.10g", r.estimate_parts.space) << ','
              << format("%.10g", r.estimate_parts.time) << ','
              << format("%.4f", r.effectivity());
        else
          csv << ",,,,,";
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
            "order            sum order       estimate order   eff.\n";
    const auto                       columns = error_columns();
    std::vector<std::vector<double>> orders;
    for (unsigned int c = 0; c < 4; ++c)
      orders.push_back(orders_of(table, columns[c].second));
    orders.push_back(
      orders_of(table, [](const Row &r) { return r.estimate.sum(); }));
    for (unsigned int i = 0; i < table.size(); ++i)
      {
        const Row &r = table[i];
        char       cell[128];
        std::snprintf(cell,
                      sizeof(cell),
                      "%5u %8llu %8llu %9.3e %9.3e %6u",
                      r.cycle,
                      r.cells,
                      r.dofs,
                      r.h,
                      r.k,
                      r.steps);
        text << cell;
        if (with_times)
          text << format(" %10.3f", r.wall_time);
        for (unsigned int c = 0; c < 4 && r.has_errors; ++c)
          {
            const std::string order = (i > 0 && table[i - 1].has_errors) ?
                                        format("%.2f", orders[c][i]) :
                                        "";
            std::snprintf(cell,
                          sizeof(cell),
                          " %14.6e %*s",
                          columns[c].second(r),
                          6,
                          order.c_str());
            text << cell;
          }
        if (r.has_estimate)
          text << estimate_text(r,
                                i > 0 && table[i - 1].has_estimate ?
                                  orders[4][i] :
                                  std::numeric_limits<double>::quiet_NaN());
        text << '\n';
      }
    return text.str();
  }
} // namespace VPContact
