// Unit test: the errors of Theorem 2 between snapshots on nested meshes.
// A coarse cell [0,2] x [0,1] carries bilinear fields; the reference cells
// (its four children, one of them refined again) carry the same fields, or
// the same plus a known perturbation: the errors are 0, or the norms of the
// perturbation (sqrt(2) |perturbation| on an area of 2). A reference that
// does not cover the run, or lies elsewhere, is refused.
#include <vpcontact/postprocess/reference_solution.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <cstdio>
#include <iostream>

using namespace dealii;
using namespace VPContact;

namespace
{
  Point<2>
  physical(const Point<2> &unit)
  {
    return Point<2>(2. * unit[0], unit[1]);
  }

  // The fields: bilinear displacement, damage and stress (plus a
  // perturbation of size @p p: u_x += p x, sigma_xx += 3 p, zeta += p / 2).
  Tensor<1, 2>
  u(const Point<2> &x, const double p)
  {
    return Tensor<1, 2>(
      {0.1 + 0.2 * x[0] - 0.3 * x[1] + 0.4 * x[0] * x[1] + p * x[0],
       -0.2 * x[0] + 0.5 * x[1] * x[0]});
  }

  double
  zeta(const Point<2> &x, const double p)
  {
    return 0.25 + 0.1 * x[0] + 0.2 * x[1] - 0.05 * x[0] * x[1] + p / 2;
  }

  SymmetricTensor<2, 2>
  sigma(const Point<2> &x, const double p)
  {
    SymmetricTensor<2, 2> s;
    s[0][0] = 10 + 3 * x[0] * x[1] + 3 * p;
    s[1][1] = -4 + x[1];
    s[0][1] = 2 * x[0] - x[0] * x[1];
    return s;
  }

  // A cell given by its path of children below coarse cell 0: the unit
  // vertices and Gauss points mapped up the path to [0,1]^2, then scaled.
  void
  add(Snapshot<2> &s, const std::vector<std::uint8_t> &path, const double p)
  {
    const auto up = [&](Point<2> x) {
      for (unsigned int i = path.size(); i > 0; --i)
        x = GeometryInfo<2>::child_to_cell_coordinates(x, path[i - 1]);
      return physical(x);
    };
    std::array<Point<2>, 4>              vertices;
    std::array<Tensor<1, 2>, 4>          displacement;
    std::array<double, 4>                damage;
    std::array<SymmetricTensor<2, 2>, 4> stress;
    const QGauss<2>                      gauss(2);
    for (unsigned int v = 0; v < 4; ++v)
      {
        vertices[v]     = up(GeometryInfo<2>::unit_cell_vertex(v));
        displacement[v] = u(vertices[v], p);
        damage[v]       = zeta(vertices[v], p);
        stress[v]       = sigma(up(gauss.point(v)), p);
      }
    s.add_cell(CellId(0, path), vertices, displacement, damage, stress);
  }

  Snapshot<2>
  reference(const double p)
  {
    Snapshot<2> s;
    s.has_damage = true;
    for (std::uint8_t c = 0; c < 3; ++c)
      add(s, {c}, p);
    for (std::uint8_t c = 0; c < 4; ++c)
      add(s, {3, c}, p);
    return s;
  }

  void
  print(const std::string &what, const ErrorNorms &e)
  {
    std::printf("%s: u %.10f  sigma %.10f  zeta %.10f\n",
                what.c_str(),
                e.displacement,
                e.stress,
                e.damage);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Snapshot<2>                      run;
  run.has_damage = true;
  add(run, {}, 0.);

  print("same fields",
        compute_errors(run, reference(0.), "ref", MPI_COMM_WORLD));
  print("perturbed (expect 1.4142135624, 4.2426406871, 0.7071067812)",
        compute_errors(run, reference(1.), "ref", MPI_COMM_WORLD));

  // Round trip through the file format.
  const Snapshot<2> read_back
    = Snapshot<2>::from_bytes(reference(1.).to_bytes(), "bytes");
  print("after to_bytes/from_bytes",
        compute_errors(run, read_back, "ref", MPI_COMM_WORLD));

  // The run finer than the reference somewhere: not covered.
  Snapshot<2> fine_run;
  fine_run.has_damage = true;
  for (std::uint8_t c = 0; c < 4; ++c)
    add(fine_run, {c}, 0.);
  Snapshot<2> coarse_reference;
  coarse_reference.has_damage = true;
  add(coarse_reference, {}, 0.);
  try
    {
      compute_errors(fine_run, coarse_reference, "ref", MPI_COMM_WORLD);
      std::cout << "NOT refused: reference coarser than the run" << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      std::cout << "refused:";
      e.print_info(std::cout);
    }

  // The same cell ids on another geometry.
  Snapshot<2> moved = reference(0.);
  Snapshot<2> shifted;
  shifted.has_damage = true;
  {
    std::array<Point<2>, 4>              vertices;
    std::array<Tensor<1, 2>, 4>          displacement;
    std::array<double, 4>                damage;
    std::array<SymmetricTensor<2, 2>, 4> stress;
    for (unsigned int c = 0; c < moved.n_cells(); ++c)
      {
        for (unsigned int v = 0; v < 4; ++v)
          {
            vertices[v]     = moved.vertex(c, v) + Point<2>(0.5, 0);
            displacement[v] = moved.displacement(c, v);
            damage[v]       = moved.damage(c, v);
            stress[v]       = moved.stress(c, v);
          }
        shifted.add_cell(CellId(moved.id(c)),
                         vertices,
                         displacement,
                         damage,
                         stress);
      }
  }
  try
    {
      compute_errors(run, shifted, "ref", MPI_COMM_WORLD);
      std::cout << "NOT refused: reference on another geometry" << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      std::cout << "refused:";
      e.print_info(std::cout);
    }
}
