// Unit test: the statistics table as CSV. Columns keep the order of first
// use, a row without a value leaves the cell empty, numbers keep 10
// significant digits.
#include <vpcontact/postprocess/statistics.h>

#include <iostream>

int
main()
{
  VPContact::Statistics statistics;
  statistics.start_row();
  statistics.add_value("step", 0u);
  statistics.add_value("time", 0.);
  statistics.start_row();
  statistics.add_value("step", 1u);
  statistics.add_value("time", 0.1);
  statistics.add_value("error", 1.234567890123e-16);
  statistics.start_row();
  statistics.add_value("step", 2u);
  statistics.add_value("dofs", 123456789012ull);
  std::cout << statistics.to_csv() << "rows: " << statistics.n_rows()
            << std::endl;
}
