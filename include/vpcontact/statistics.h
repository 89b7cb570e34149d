// The run's statistics table: one row per time step, one named column per
// quantity, written as CSV.
#ifndef vpcontact_statistics_h
#define vpcontact_statistics_h

#include <map>
#include <string>
#include <vector>

namespace VPContact
{
  /**
   * A table with one row per time step. Columns appear in the order in which
   * they are first given a value; a row that has no value for a column
   * leaves it empty in the CSV. Values are formatted once, when added, with
   * 10 significant digits.
   */
  class Statistics
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

    std::vector<std::string>                        columns;
    std::vector<std::map<std::string, std::string>> rows;
  };
} // namespace VPContact

#endif
