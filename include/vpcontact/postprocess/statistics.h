// The run's statistics table: one row per time step, one named column per
// quantity, kept in deal.II's TableHandler and written as CSV.
#ifndef vpcontact_statistics_h
#define vpcontact_statistics_h

#include <deal.II/base/table_handler.h>

#include <string>

namespace VPContact
{
  /**
   * A deal.II TableHandler with one row per time step, written as the CSV
   * of statistics.csv (TableHandler writes aligned text and LaTeX, not
   * CSV). Columns appear in the order in which they are first given a
   * value; a row that has no value for a column leaves it empty. Values are
   * formatted once, when added, with 10 significant digits, and kept as
   * text, so that a table read back from its CSV (a resumed run) writes the
   * same text again.
   */
  class Statistics : public dealii::TableHandler
  {
  public:
    /// Open a new row; later add_value() calls fill it.
    void
    start_row();

    void
    add_value(const std::string &column, const double value);

    void
    add_value(const std::string &column, const unsigned long long value);

    void
    add_value(const std::string &column, const unsigned int value);

    /// The whole table as CSV text, header row first.
    std::string
    to_csv() const;

    unsigned int
    n_rows() const;

    /**
     * Replace the table by the one in @p csv, the text of an earlier
     * to_csv() (a resumed run continues its table). Throws if a row has
     * more cells than the header.
     */
    void
    read_csv(const std::string &csv);

  private:
    void
    add_text(const std::string &column, const std::string &text);

    unsigned int rows = 0;
  };
} // namespace VPContact

#endif
