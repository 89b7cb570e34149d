// Unit test: the uniform time grid. T = 1, k = 0.1 has N = 10 steps (1/0.1 is
// not exactly 10 in binary) and t_N is exactly T; T = 1, k = 0.3 is refused
// with a message naming Time/Time step.
#include <vpcontact/simulator/time_discretization.h>

#include <deal.II/base/exceptions.h>

#include <iostream>

using namespace VPContact;

void
try_grid(const std::string &end_time, const std::string &step)
{
  ParameterHandler prm;
  TimeDiscretization::declare_parameters(prm);
  prm.enter_subsection("Time");
  prm.set("End time", end_time);
  prm.set("Time step", step);
  prm.leave_subsection();
  TimeDiscretization time;
  try
    {
      time.parse_parameters(prm);
      std::cout << "T = " << end_time << ", k = " << step
                << ": N = " << time.n_steps() << ", t_N == T: "
                << (time.time(time.n_steps()) == time.end_time())
                << ", t_3 = " << time.time(3) << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      std::cout << "T = " << end_time << ", k = " << step << ": refused: ";
      e.print_info(std::cout);
    }
}

int
main()
{
  deal_II_exceptions::disable_abort_on_exception();
  try_grid("1", "0.1");
  try_grid("1", "0.01");
  try_grid("1", "0.3");
  try_grid("0", "0.1");
}
