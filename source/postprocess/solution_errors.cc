// The errors of Theorem 2 between a run and a reference whose mesh refines
// the run's: the run's Q1 fields and Gauss-point stress evaluated exactly on
// the reference's cells.
#include <vpcontact/input/input_error.h>
#include <vpcontact/postprocess/reference_solution.h>

#include <deal.II/base/quadrature_lib.h>

#include <cmath>
#include <map>
#include <optional>

namespace VPContact
{
  namespace
  {
    // The Q1 shape function of vertex v on the unit cell (deal.II numbers
    // vertices lexicographically: bit d of v says which end in direction d).
    template <int dim>
    double
    q1_value(const unsigned int v, const Point<dim> &p)
    {
      double value = 1;
      for (unsigned int d = 0; d < dim; ++d)
        value *= ((v >> d) & 1) ? p[d] : 1. - p[d];
      return value;
    }

    template <int dim>
    Tensor<1, dim>
    q1_gradient(const unsigned int v, const Point<dim> &p)
    {
      Tensor<1, dim> gradient;
      for (unsigned int d = 0; d < dim; ++d)
        {
          gradient[d] = ((v >> d) & 1) ? 1. : -1.;
          for (unsigned int e = 0; e < dim; ++e)
            if (e != d)
              gradient[d] *= ((v >> e) & 1) ? p[e] : 1. - p[e];
        }
      return gradient;
    }

    // The Lagrange function of Gauss point q of QGauss<dim>(2) (points
    // (1 -+ 1/sqrt 3)/2 in each direction, x fastest): the interpolation
    // through the stress values at the quadrature points.
    template <int dim>
    double
    gauss_lagrange(const unsigned int q, const Point<dim> &p)
    {
      const double g0 = 0.5 - 0.5 / std::sqrt(3.),
                   g1 = 0.5 + 0.5 / std::sqrt(3.);
      double value    = 1;
      for (unsigned int d = 0; d < dim; ++d)
        value
          *= ((q >> d) & 1) ? (p[d] - g0) / (g1 - g0) : (p[d] - g1) / (g0 - g1);
      return value;
    }

    // Fields of cell c of a snapshot at the unit point p.
    template <int dim>
    struct CellFields
    {
      const Snapshot<dim> &s;
      const unsigned int   c;

      Point<dim>
      position(const Point<dim> &p) const
      {
        Point<dim> x;
        for (unsigned int v = 0; v < Snapshot<dim>::n_vertices; ++v)
          x += q1_value(v, p) * s.vertex(c, v);
        return x;
      }

      Tensor<2, dim>
      jacobian(const Point<dim> &p) const
      {
        Tensor<2, dim> J;
        for (unsigned int v = 0; v < Snapshot<dim>::n_vertices; ++v)
          J += outer_product(s.vertex(c, v), q1_gradient(v, p));
        return J;
      }

      SymmetricTensor<2, dim>
      strain(const Point<dim> &p) const
      {
        Tensor<2, dim> unit_gradient;
        for (unsigned int v = 0; v < Snapshot<dim>::n_vertices; ++v)
          unit_gradient
            += outer_product(s.displacement(c, v), q1_gradient(v, p));
        return symmetrize(unit_gradient * invert(jacobian(p)));
      }

      double
      damage(const Point<dim> &p) const
      {
        double zeta = 0;
        for (unsigned int v = 0; v < Snapshot<dim>::n_vertices; ++v)
          zeta += q1_value(v, p) * s.damage(c, v);
        return zeta;
      }

      SymmetricTensor<2, dim>
      stress(const Point<dim> &p) const
      {
        SymmetricTensor<2, dim> sigma;
        for (unsigned int q = 0; q < Snapshot<dim>::n_vertices; ++q)
          sigma += gauss_lagrange(q, p) * s.stress(c, q);
        return sigma;
      }
    };

    // The volume of a cell of a snapshot (Gauss rule, exact for Q1 maps).
    template <int dim>
    double
    volume(const CellFields<dim> &cell)
    {
      const QGauss<dim> gauss(2);
      double            v = 0;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        v += determinant(cell.jacobian(gauss.point(q))) * gauss.weight(q);
      return v;
    }

    // The cell of the run that contains reference cell C: the longest
    // prefix of C's path of children that is a cell of the run. Returns
    // the run's index and the length of that prefix, or no index.
    template <int dim>
    std::pair<std::optional<unsigned int>, unsigned int>
    containing_cell(const std::map<CellId::binary_type, unsigned int> &cells,
                    const CellId                                      &id)
    {
      const auto path = id.get_child_indices();
      for (unsigned int depth = path.size() + 1; depth-- > 0;)
        {
          const CellId prefix(id.get_coarse_cell_id(), depth, path.data());
          const auto   found = cells.find(prefix.template to_binary<dim>());
          if (found != cells.end())
            return {found->second, depth};
        }
      return {std::nullopt, 0};
    }

    // Add the squared errors on reference cell C (inside run cell A, whose
    // path from A is path[depth..]) to @p squares, and the distance between
    // C's vertices and their images through A's map to @p mismatch.
    template <int dim>
    void
    add_cell_errors(const CellFields<dim>               &fine,
                    const CellFields<dim>               &coarse,
                    const ArrayView<const std::uint8_t> &path,
                    const unsigned int                   depth,
                    double                               squares[3],
                    double                              &mismatch)
    {
      const auto to_coarse = [&](Point<dim> p) {
        for (unsigned int i = path.size(); i > depth; --i)
          p = GeometryInfo<dim>::child_to_cell_coordinates(p, path[i - 1]);
        return p;
      };
      for (unsigned int v = 0; v < Snapshot<dim>::n_vertices; ++v)
        mismatch = std::max(
          mismatch,
          coarse.position(to_coarse(GeometryInfo<dim>::unit_cell_vertex(v)))
            .distance(fine.s.vertex(fine.c, v)));

      const QGauss<dim> gauss(2);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const Point<dim> p   = gauss.point(q);
          const Point<dim> p_A = to_coarse(p);
          const double JxW = determinant(fine.jacobian(p)) * gauss.weight(q);
          const auto   e_strain = fine.strain(p) - coarse.strain(p_A);
          const auto   e_stress = fine.s.stress(fine.c, q) - coarse.stress(p_A);
          const double e_damage = fine.damage(p) - coarse.damage(p_A);
          squares[0] += (e_strain * e_strain) * JxW;
          squares[1] += (e_stress * e_stress) * JxW;
          squares[2] += e_damage * e_damage * JxW;
        }
    }

    // Throw unless the run and the reference both have a damage field or
    // both have none.
    template <int dim>
    void
    check_same_fields(const Snapshot<dim> &run,
                      const Snapshot<dim> &reference,
                      const std::string   &reference_name)
    {
      AssertThrow(run.has_damage == reference.has_damage,
                  ExcMessage("The reference " + reference_name
                             + (reference.has_damage ? " has" : " has no")
                             + " damage field, this run"
                             + (run.has_damage ? " has one." : " has none.")
                             + " Compare runs of the same scene."));
    }

    // Throw unless the reference refines the run's mesh: the reference's
    // cells that lie in cells of the run (volume @p covered) and the run's
    // cells (volume @p run_volume) both fill the reference's volume
    // @p total, and the reference's vertices are where the run's cells map
    // them (@p mismatch, the largest distance, is small against the size
    // @p scale of the body).
    void
    check_reference_refines_run(const std::string &reference_name,
                                const double       total,
                                const double       covered,
                                const double       run_volume,
                                const double       mismatch,
                                const double       scale)
    {
      AssertThrow(
        std::abs(covered - total) <= 1e-9 * total
          && std::abs(run_volume - total) <= 1e-9 * total,
        ExcMessage("The reference " + reference_name
                   + " is not a refinement of this run's mesh: of its volume "
                   + to_text(total) + ", " + to_text(covered)
                   + " lies in cells of this run (volume " + to_text(run_volume)
                   + "). The reference must start from the same coarse mesh "
                     "(Geometry) and be at least as fine everywhere: refine "
                     "it more (Geometry/Global refinements) than any cycle."));
      AssertThrow(mismatch <= 1e-9 * scale,
                  ExcMessage("The reference " + reference_name
                             + " has its cells elsewhere than this run (by "
                             + to_text(mismatch)
                             + "): it was computed on another geometry."));
    }
  } // namespace



  template <int dim>
  ErrorNorms
  compute_errors(const Snapshot<dim> &run,
                 const Snapshot<dim> &reference,
                 const std::string   &reference_name,
                 const MPI_Comm       communicator)
  {
    check_same_fields(run, reference, reference_name);
    std::map<CellId::binary_type, unsigned int> run_cells;
    for (unsigned int a = 0; a < run.n_cells(); ++a)
      run_cells[run.id(a)] = a;

    // Every reference cell in the run cell that contains it; the volumes
    // tell whether the reference covers the run.
    double squares[3] = {0, 0, 0};
    double covered = 0, total = 0, run_volume = 0, mismatch = 0;
    for (unsigned int c = 0; c < reference.n_cells(); ++c)
      {
        const CellFields<dim> fine{reference, c};
        const double          v = volume(fine);
        total += v;
        const CellId id(reference.id(c));
        const auto [a, depth] = containing_cell<dim>(run_cells, id);
        if (!a)
          continue;
        covered += v;
        add_cell_errors(fine,
                        CellFields<dim>{run, *a},
                        id.get_child_indices(),
                        depth,
                        squares,
                        mismatch);
      }
    for (unsigned int a = 0; a < run.n_cells(); ++a)
      run_volume += volume(CellFields<dim>{run, a});

    covered            = Utilities::MPI::sum(covered, communicator);
    run_volume         = Utilities::MPI::sum(run_volume, communicator);
    mismatch           = Utilities::MPI::max(mismatch, communicator);
    const double scale = std::pow(total, 1. / dim);
    check_reference_refines_run(reference_name,
                                total,
                                covered,
                                run_volume,
                                mismatch,
                                scale);

    Utilities::MPI::sum(ArrayView<const double>(squares, 3),
                        communicator,
                        ArrayView<double>(squares, 3));
    return {std::sqrt(squares[0]),
            std::sqrt(squares[1]),
            std::sqrt(squares[2])};
  }



  template ErrorNorms
  compute_errors(const Snapshot<2> &,
                 const Snapshot<2> &,
                 const std::string &,
                 const MPI_Comm);
  template ErrorNorms
  compute_errors(const Snapshot<3> &,
                 const Snapshot<3> &,
                 const std::string &,
                 const MPI_Comm);
} // namespace VPContact
