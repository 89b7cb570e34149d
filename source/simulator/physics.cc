// The defaults of the Physics interface: no part in that call.
#include <vpcontact/simulator/physics.h>

namespace VPContact
{
  template <int dim>
  void
  Physics<dim>::setup_on_mesh(const SimulatorAccess<dim> &,
                              LA::MPI::BlockVector &)
  {}



  template <int dim>
  std::optional<ScalarNodeSpace<dim>>
  Physics<dim>::node_space() const
  {
    return std::nullopt;
  }



  template <int dim>
  bool
  Physics<dim>::solves_in_step() const
  {
    return false;
  }



  template <int dim>
  void
  Physics<dim>::solve_step(const unsigned int,
                           const LA::MPI::BlockVector &,
                           const StressHistory<dim> &)
  {}



  template <int dim>
  void
  Physics<dim>::store(const unsigned int, LA::MPI::BlockVector &)
  {}



  template <int dim>
  bool
  Physics<dim>::reports_before_errors() const
  {
    return false;
  }



  template <int dim>
  std::vector<std::string>
  Physics<dim>::solution_field_names() const
  {
    return {};
  }



  template <int dim>
  std::vector<NodalField<dim>>
  Physics<dim>::output_fields(const OwnedLayout &) const
  {
    return {};
  }



  template <int dim>
  std::string
  Physics<dim>::iteration_counts() const
  {
    return "";
  }



  template <int dim>
  std::string
  Physics<dim>::work_summary() const
  {
    return "";
  }



  template <int dim>
  void
  Physics<dim>::read_transferred_state(
    const LA::MPI::Vector                            &sets_owned,
    const LA::MPI::Vector                            &sets,
    const std::function<double(const std::string &)> &counter)
  {
    read_checkpoint(sets_owned, sets, counter);
  }



  template class Physics<2>;
  template class Physics<3>;
} // namespace VPContact
