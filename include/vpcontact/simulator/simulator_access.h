// What the simulator shares with the physics objects it conducts: the
// mesh, its element and degrees of freedom, the clock, the timer and the
// output folder, in the manner of ASPECT's SimulatorAccess.
#ifndef vpcontact_simulator_access_h
#define vpcontact_simulator_access_h

#include <vpcontact/damage/damage_model.h>
#include <vpcontact/fe/discretization.h>
#include <vpcontact/postprocess/output_writer.h>
#include <vpcontact/simulator/time_discretization.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>

namespace VPContact
{
  using namespace dealii;

  /**
   * References to what the simulator owns and a physics object reads: the
   * communicator, the screen and the timer, the element and rules of the
   * mesh's cell type, the mesh and its degrees of freedom (numbered by
   * blocks: displacement, then damage), the time grid, whether the scene
   * has damage, and the output folder (named in messages). The simulator
   * makes one and hands it to each physics object it builds; the objects
   * outlive none of these.
   */
  template <int dim>
  struct SimulatorAccess
  {
    MPI_Comm                                mpi_communicator;
    const ConditionalOStream               &pcout;
    TimerOutput                            &computing_timer;
    const Discretization<dim>              &discretization;
    const parallel::TriangulationBase<dim> &triangulation;
    const FESystem<dim>                    &fe;
    const Quadrature<dim>                  &quadrature;
    const Mapping<dim>                     &mapping;
    const DoFHandler<dim>                  &dof_handler;
    const IndexSet                         &locally_owned_dofs;
    const IndexSet                         &locally_relevant_dofs;
    const TimeDiscretization               &time_discretization;
    const DamageModel<dim>                 &damage_model;
    const OutputWriter<dim>                &output_writer;
  };
} // namespace VPContact

#endif
