// Unit test: CellKinematics against known answers and against FEValues, on a
// distorted mesh (vertices moved at random, so the cells are general
// quadrilaterals and hexahedra) with one level of local refinement (hanging
// nodes), in 2D and 3D, with the FESystem of the simulator (dim displacement
// components and the damage), serial and on 2 ranks. Q1 runs the kernels of
// fixed_size_cell_kernels.h, Q2 the general loops.
//  * u = A x + b, zeta = c . x + d interpolated: Q1 reproduces them, so at
//    every quadrature point eps(u) = sym(A) and zeta = c . x_q exactly.
//  * A random vector: strains, damage and the work of a random stress on
//    the test functions agree with those of FEValues.
#include <vpcontact/fe/cell_kinematics.h>
#include <vpcontact/linear_algebra/linear_algebra.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <cstdio>
#include <random>
#include <string>

using namespace VPContact;

namespace
{
  // u = A x + b in the first dim components, zeta = c . x + d in the last.
  template <int dim>
  class AffineField : public Function<dim>
  {
  public:
    AffineField()
      : Function<dim>(dim + 1)
    {}

    double
    value(const Point<dim> &x, const unsigned int component) const override
    {
      if (component == dim)
        return 0.25 + 0.5 * x[0] - 0.125 * x[dim - 1];
      double value = 0.1 * (component + 1);
      for (unsigned int d = 0; d < dim; ++d)
        value += A(component, d) * x[d];
      return value;
    }

    static double
    A(const unsigned int i, const unsigned int j)
    {
      return 0.3 * (i + 1) - 0.7 * j + 0.2 * i * j;
    }
  };



  template <int dim>
  void
  check(const MPI_Comm comm, const unsigned int degree)
  {
    parallel::distributed::Triangulation<dim> triangulation(comm);
    GridGenerator::subdivided_hyper_cube(triangulation, 4);
    GridTools::distort_random(0.25, triangulation, true, 7);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < 0.4)
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();

    const FESystem<dim> fe(FE_Q<dim>(degree), dim, FE_Q<dim>(degree), 1);
    DoFHandler<dim>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const QGauss<dim> quadrature(degree + 1);

    LA::MPI::Vector     owned_vector(owned, comm);
    LA::MPI::Vector     ghosted(owned, relevant, comm);
    CellKinematics<dim> kinematics;
    kinematics.reinit(dof_handler, quadrature, ghosted);

    // Known answer: the affine field.
    VectorTools::interpolate(dof_handler, AffineField<dim>(), owned_vector);
    ghosted = owned_vector;
    Tensor<2, dim> A;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        A[i][j] = AffineField<dim>::A(i, j);
    const SymmetricTensor<2, dim>        sym_A = symmetrize(A);
    std::vector<SymmetricTensor<2, dim>> strains(quadrature.size());
    std::vector<double>                  damage(quadrature.size());
    double                               strain_error = 0, damage_error = 0;
    const double *entries = kinematics.local_entries(ghosted);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          kinematics.strains(cell, entries, make_array_view(strains));
          kinematics.damage(cell, entries, make_array_view(damage));
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              strain_error
                = std::max(strain_error, (strains[q] - sym_A).norm());
              damage_error = std::max(
                damage_error,
                std::abs(
                  damage[q]
                  - AffineField<dim>().value(kinematics.point(cell, q), dim)));
            }
        }

    // A random field and a random stress, against FEValues.
    std::mt19937                           random(11);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (const auto i : owned)
      owned_vector[i] = uniform(random);
    ghosted = owned_vector;
    entries = kinematics.local_entries(ghosted);
    FEValues<dim>                        fe_values(fe,
                            quadrature,
                            update_values | update_gradients
                              | update_JxW_values);
    const FEValuesExtractors::Vector     u(0);
    const FEValuesExtractors::Scalar     zeta(dim);
    std::vector<SymmetricTensor<2, dim>> fe_strains(quadrature.size());
    std::vector<double>                  fe_damage(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> stress(quadrature.size());
    Vector<double>                       work(fe.n_dofs_per_cell());
    double strain_difference = 0, damage_difference = 0, work_difference = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_symmetric_gradients(ghosted, fe_strains);
          fe_values[zeta].get_function_values(ghosted, fe_damage);
          kinematics.strains(cell, entries, make_array_view(strains));
          kinematics.damage(cell, entries, make_array_view(damage));
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              strain_difference = std::max(strain_difference,
                                           (strains[q] - fe_strains[q]).norm());
              damage_difference = std::max(damage_difference,
                                           std::abs(damage[q] - fe_damage[q]));
              for (unsigned int c = 0;
                   c < SymmetricTensor<2, dim>::n_independent_components;
                   ++c)
                stress[q].access_raw_entry(c) = uniform(random);
            }
          work = 0.;
          kinematics.subtract_stress_work(cell,
                                          make_array_view(
                                            std::as_const(stress)),
                                          work);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              double expected = 0;
              if (fe.system_to_component_index(i).first < dim)
                for (unsigned int q = 0; q < quadrature.size(); ++q)
                  expected -= stress[q] * fe_values[u].symmetric_gradient(i, q);
              work_difference
                = std::max(work_difference, std::abs(work(i) - expected));
            }
        }

    const auto verdict = [&](const double difference) {
      return Utilities::MPI::max(difference, comm) < 1e-12 ? "< 1e-12" :
                                                             "LARGE";
    };
    const std::string strain          = verdict(strain_error),
                      damage_value    = verdict(damage_error),
                      fe_strain       = verdict(strain_difference),
                      fe_damage_value = verdict(damage_difference),
                      fe_work         = verdict(work_difference);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::printf(
        "%dD Q%u, %u cells: affine field: strain error %s, damage error "
        "%s; random field against FEValues: strain %s, damage %s, "
        "stress work %s\n",
        dim,
        degree,
        triangulation.n_global_active_cells(),
        strain.c_str(),
        damage_value.c_str(),
        fe_strain.c_str(),
        fe_damage_value.c_str(),
        fe_work.c_str());
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  for (const unsigned int degree : {1, 2})
    {
      check<2>(comm, degree);
      check<3>(comm, degree);
    }
}
