// Unit test: distribute_constraints() computes what
// AffineConstraints::distribute() computes, serial and on 2 ranks. A Q1
// vector field on a unit square with one corner cell refined twice (hanging
// nodes, whose constraints read their parents) and an inhomogeneous
// Dirichlet value on the left side; the vector holds arbitrary values (a
// smooth function, the constrained entries wrong on purpose). On one rank the
// constraints read only owned entries and are applied in place; on 2 ranks
// some hanging nodes read a neighbour's entries and distribute() runs. Either
// way the result must be the same bits. A Dirichlet-only set is checked too.
#include <vpcontact/fe/owned_constraints.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>

#include <cstdio>
#include <string>

#include "corner_refined_mesh.h"

using namespace VPContact;

namespace
{
  // The largest |a_i - b_i| over the owned entries of all ranks.
  double
  largest_difference(const LA::MPI::Vector &a,
                     const LA::MPI::Vector &b,
                     const MPI_Comm         comm)
  {
    double difference = 0.;
    for (unsigned int i = 0; i < a.locally_owned_size(); ++i)
      difference = std::max(difference, std::abs(a.begin()[i] - b.begin()[i]));
    return Utilities::MPI::max(difference, comm);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);

  CornerRefinedMesh mesh(comm, 3);
  const auto       &dof_handler = mesh.dof_handler;
  const IndexSet   &owned       = mesh.owned;
  const IndexSet   &relevant    = mesh.relevant;

  const auto build = [&](const bool with_hanging_nodes) {
    AffineConstraints<double> constraints(relevant);
    if (with_hanging_nodes)
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(
      dof_handler,
      0,
      Functions::ConstantFunction<2>(0.25, 2),
      constraints);
    constraints.close();
    return constraints;
  };

  LA::MPI::Vector values(owned, comm);
  for (const auto i : owned)
    values[i] = std::sin(0.37 * i) + 0.01 * i;
  values.compress(VectorOperation::insert);

  const auto report = [&](const std::string &what,
                          const double       moved,
                          const double       difference) {
    if (rank == 0)
      std::printf("%s: entries moved: %s, largest difference: %s\n",
                  what.c_str(),
                  moved > 0.1 ? "yes" : "no",
                  difference == 0. ? "0" : std::to_string(difference).c_str());
  };
  // Hanging nodes and Dirichlet: against distribute().
  {
    const AffineConstraints<double> constraints = build(true);
    LA::MPI::Vector                 expected(values);
    LA::MPI::Vector                 computed(values);
    constraints.distribute(expected);
    distribute_constraints(constraints, computed);
    report("hanging nodes and Dirichlet, against distribute()",
           largest_difference(values, computed, comm),
           largest_difference(expected, computed, comm));
  }

  // Dirichlet alone: the known answer, 0.25 on the constrained entries and
  // the values elsewhere. (deal.II 9.4's distribute() throws from Epetra
  // here on 2 ranks, where one rank holds no constraint.)
  {
    const AffineConstraints<double> constraints = build(false);
    LA::MPI::Vector                 expected(values);
    LA::MPI::Vector                 computed(values);
    for (const auto i : owned)
      if (constraints.is_constrained(i))
        expected[i] = 0.25;
    expected.compress(VectorOperation::insert);
    distribute_constraints(constraints, computed);
    report("Dirichlet only, against the known values",
           largest_difference(values, computed, comm),
           largest_difference(expected, computed, comm));
  }
}
