// Checks that the --print-parameters listing is a valid parameter file: the
// listing of every declared entry (2D and 3D) is read back by a fresh
// ParameterHandler without error, and every section named in the
// documentation is there.
#include <vpcontact/input/parameter_listing.h>
#include <vpcontact/simulator/simulator.h>

#include <iostream>
#include <sstream>

using namespace VPContact;

template <int dim>
void
check()
{
  ParameterHandler prm;
  Simulator<dim>::declare_parameters(prm);
  std::ostringstream listing;
  print_parameter_listing(prm, listing);

  ParameterHandler reread;
  Simulator<dim>::declare_parameters(reread);
  reread.parse_input_from_string(listing.str());
  std::cout << dim << "D listing re-read: ok" << std::endl;

  for (const std::string section : {"Geometry",
                                    "Material",
                                    "Boundary conditions",
                                    "Contact",
                                    "Time",
                                    "Solver",
                                    "Output",
                                    "Verification",
                                    "Checkpoint"})
    std::cout << "  section " << section << ": "
              << (listing.str().find("subsection " + section)
                      != std::string::npos ?
                    "present" :
                    "MISSING")
              << std::endl;
}

int
main()
{
  check<2>();
  check<3>();
}
