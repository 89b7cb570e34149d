// The defaults of the Physics interface.
#include <vpcontact/simulator/physics.h>

namespace VPContact
{
  std::string
  Physics::iteration_counts() const
  {
    return "";
  }
} // namespace VPContact
