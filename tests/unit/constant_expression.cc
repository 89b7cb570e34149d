// Unit test: is_constant_expression() tells an expression whose value is the
// same at every point and time (numbers, named constants, operators) from
// one that names a variable or calls a function.
#include <vpcontact/input/parsed_function.h>

#include <iostream>

using namespace VPContact;

void
show(const std::string &expression)
{
  std::cout << "'" << expression << "': "
            << (is_constant_expression(expression, coordinate_variables(2)) ?
                  "constant" :
                  "varies")
            << std::endl;
}

int
main()
{
  show("1");
  show("0.75");
  show("1e-3");
  show("2.5E+2 * 4");
  show(".5");
  show("lambda_w - 0.5*lambda_E"); // named constants only
  show("1 - x2");                  // a constant named x2, not x
  show("x");                       // a coordinate
  show("1 - 0.5*y");               // a coordinate in a sum
  show("exp(-t)");                 // time, and a function
  show("sqrt(2)");                 // a function of a constant: not assumed
  show("rand()");                  // a function without arguments
  show("rand ()");                 // the same, with a space
  show("x1 > 0 ? 1 : 0.5");        // a constant named x1
  show("1e-3*z");                  // z is no variable in 2D
  show("");                        // empty
}
