// Unit test: DamageSystem::solve() with nodes held at their bound. On a
// distributed 12 x 12 mesh of the unit square with the FESystem of a damage
// scene (Q1^2 x Q1), K = M_L/k + kappa A is assembled in the compact damage
// numbering, a vector x* is chosen that is zero on the held nodes (those with
// x < 0.4) and smooth elsewhere, and b = (K x*) on the free nodes, 0 on the
// held ones. The masked CG must return x* (K_FF x_F = b_F has the unique
// solution x*_F), with the held entries exactly zero, for every
// preconditioner (the region solver's two, the libraries' incomplete Cholesky
// and AMG) with both packages (Trilinos and PETSc), from a zero start vector
// and from x* itself, for five held sets in turn (x < 0.4, 0.6, 0.1, and y <
// 0.25, y > 0.51, which lie on part of the ranks only) with the same
// preconditioner; and DamageSystem::solve_work() must grow on every rank
// by its free nodes times the iterations. The same on 2 and 3 ranks.
#include <vpcontact/damage/damage_system.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/linear_algebra/linear_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <iostream>
#include <tuple>

using namespace VPContact;

namespace
{
  // M_L/k + kappa A on the damage shape functions of each cell, with k =
  // 0.01 and kappa = 0.01 as in the paper scene.
  void
  assemble(const DoFHandler<2> &dof_handler, DamageSystem<2> &system)
  {
    const double       k = 0.01, kappa = 0.01;
    const QGauss<2>    quadrature(2);
    FEValues<2>        fe_values(dof_handler.get_fe(),
                          quadrature,
                          update_gradients | update_JxW_values);
    const auto        &shape = system.shape_functions();
    FullMatrix<double> cell_matrix(shape.size(), shape.size());
    std::vector<types::global_dof_index> indices;
    system.matrix() = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          system.dof_indices(cell, indices);
          for (unsigned int a = 0; a < shape.size(); ++a)
            for (unsigned int b = 0; b < shape.size(); ++b)
              {
                double entry = (a == b ? cell->measure() / 4. / k : 0.);
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  entry += kappa * fe_values.shape_grad(shape[a], q)
                           * fe_values.shape_grad(shape[b], q)
                           * fe_values.JxW(q);
                cell_matrix(a, b) = entry;
              }
          system.hanging_node_constraints()
            .distribute_local_to_global(cell_matrix, indices, system.matrix());
        }
    system.matrix().compress(VectorOperation::add);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;

  parallel::distributed::Triangulation<2> triangulation(comm);
  GridGenerator::subdivided_hyper_cube(triangulation, 12);
  const FESystem<2> fe(FE_Q<2>(1), 2, FE_Q<2>(1), 1);
  DoFHandler<2>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  // Numbered by blocks, the damage last, as the simulator numbers them.
  DoFRenumbering::component_wise(dof_handler,
                                 std::vector<unsigned int>{0, 0, 1});
  IndexSet relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

  for (const std::string package : {"Trilinos", "PETSc"})
    for (const std::string preconditioner :
         {"modified diagonal incomplete Cholesky",
          "modified incomplete Cholesky",
          "incomplete Cholesky",
          "AMG"})
      {
        ParameterHandler prm;
        LinearSolver::declare_parameters(prm);
        DamageSystem<2>::declare_parameters(prm);
        prm.enter_subsection("Solver");
        prm.set("Linear algebra", package);
        prm.set("Damage preconditioner", preconditioner);
        prm.leave_subsection();
        LinearSolver linear_solver;
        linear_solver.parse_parameters(prm);
        DamageSystem<2> system;
        system.parse_parameters(prm, linear_solver.package());
        system.reinit(dof_handler,
                      2,
                      dof_handler.locally_owned_dofs(),
                      relevant,
                      comm);
        assemble(dof_handler, system);
        system.initialize_preconditioner();

        // Five held sets in turn, with the same preconditioner: x < 0.4,
        // x < 0.6, x < 0.1, y < 0.25 and y > 0.51. For each, x*: 0 on the
        // held nodes, smooth and nonzero elsewhere. The mesh's 144 coarse
        // cells are split among the ranks in rows of y, so that on 2 and 3
        // ranks the last two sets lie in part of the ranks only: y < 0.25
        // on the first rank alone, and y > 0.51 covers every node of the
        // last rank and none of the first (which must still take part in
        // every collective call of the solve).
        for (const auto &[axis, threshold, below] :
             {std::make_tuple(0u, 0.4, true),
              std::make_tuple(0u, 0.6, true),
              std::make_tuple(0u, 0.1, true),
              std::make_tuple(1u, 0.25, true),
              std::make_tuple(1u, 0.51, false)})
          {
            const auto is_held = [&](const Point<2> &p) {
              return below ? p[axis] < threshold : p[axis] > threshold;
            };
            LA::MPI::Vector                      exact(system.owned(), comm);
            std::vector<unsigned int>            held;
            std::vector<types::global_dof_index> indices;
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  system.dof_indices(cell, indices);
                  for (unsigned int v = 0; v < indices.size(); ++v)
                    if (system.owned().is_element(indices[v]))
                      {
                        const Point<2> p = cell->vertex(v);
                        exact(indices[v])
                          = (is_held(p) ?
                               0. :
                               1. + std::sin(3. * p[0]) * std::cos(2. * p[1]));
                      }
                }
            for (const auto i : system.owned())
              if (exact(i) == 0.)
                held.push_back(system.local_position(i));

            LA::MPI::Vector b(exact), x(exact);
            system.vmult_on_support(b, exact);
            for (const auto i : held)
              b.begin()[i] = 0.;

            const unsigned int n_held
              = Utilities::MPI::sum(static_cast<unsigned int>(held.size()),
                                    comm);
            if (Utilities::MPI::this_mpi_process(comm) == 0)
              std::cout << package << ", " << preconditioner << ": "
                        << system.owned().size() << " damage dofs, " << n_held
                        << " held (" << (axis == 0 ? "x" : "y")
                        << (below ? " < " : " > ") << threshold << ")"
                        << std::endl;
            for (const bool from_exact : {false, true})
              {
                if (!from_exact)
                  x = 0.;
                else
                  x = exact;
                const double       work_before = system.solve_work();
                const unsigned int iterations
                  = system.solve(b, x, held, 1e-12, 1000);
                // The rank's free nodes times the iterations, counted for
                // the load balance that a run on several ranks reports.
                const unsigned int work_counted
                  = Utilities::MPI::min(static_cast<unsigned int>(
                                          system.solve_work() - work_before
                                          == double(system.owned().n_elements()
                                                    - held.size())
                                               * iterations),
                                        comm);
                double held_max = 0;
                for (const auto i : held)
                  held_max = std::max(held_max, std::abs(x.begin()[i]));
                held_max = Utilities::MPI::max(held_max, comm);
                LA::MPI::Vector error(x);
                error -= exact;
                const double relative
                  = error.linfty_norm() / exact.linfty_norm();
                if (Utilities::MPI::this_mpi_process(comm) == 0)
                  std::cout
                    << "  start " << (from_exact ? "x*" : "0 ")
                    << ": |x - x*|/|x*| below 1e-9: "
                    << (relative < 1e-9 ? "yes" : "no")
                    << ", held entries exactly 0: "
                    << (held_max == 0. ? "yes" : "no") << ", CG iterations "
                    << (from_exact ? (iterations == 0 ? "0" : "more than 0") :
                                     (iterations > 0 ? "more than 0" : "0"))
                    << ", work counted on every rank: "
                    << (work_counted == 1 ? "yes" : "no") << std::endl;
              }
          }
      }
}
