// The element, quadrature rules and triangulation of a run, chosen by its cell
// type: Q1 on quadrilaterals (hexahedra), P1 on triangles (tetrahedra).
#include <vpcontact/fe/discretization.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>

namespace VPContact
{
  namespace
  {
    template <int dim>
    FESystem<dim>
    make_element(const bool simplex, const bool with_damage)
    {
      if (simplex)
        {
          if (with_damage)
            return FESystem<dim>(FE_SimplexP<dim>(1),
                                 dim,
                                 FE_SimplexP<dim>(1),
                                 1);
          return FESystem<dim>(FE_SimplexP<dim>(1), dim);
        }
      if (with_damage)
        return FESystem<dim>(FE_Q<dim>(1), dim, FE_Q<dim>(1), 1);
      return FESystem<dim>(FE_Q<dim>(1), dim);
    }
  } // namespace



  template <int dim>
  Discretization<dim>::Discretization(const bool simplex,
                                      const bool with_damage)
    : is_simplex(simplex)
    , fe(make_element<dim>(simplex, with_damage))
    , cell_rule(simplex ? Quadrature<dim>(QGaussSimplex<dim>(1)) :
                          Quadrature<dim>(QGauss<dim>(2)))
    , face_rule(simplex ? Quadrature<dim - 1>(QGaussSimplex<dim - 1>(2)) :
                          Quadrature<dim - 1>(QGauss<dim - 1>(2)))
  {}



  template <int dim>
  bool
  Discretization<dim>::simplex() const
  {
    return is_simplex;
  }



  template <int dim>
  const FESystem<dim> &
  Discretization<dim>::finite_element() const
  {
    return fe;
  }



  template <int dim>
  const Quadrature<dim> &
  Discretization<dim>::quadrature() const
  {
    return cell_rule;
  }



  template <int dim>
  const Mapping<dim> &
  Discretization<dim>::mapping() const
  {
    return fe.reference_cell().template get_default_linear_mapping<dim>();
  }



  template <int dim>
  const Quadrature<dim - 1> &
  Discretization<dim>::face_quadrature() const
  {
    return face_rule;
  }



  template <int dim>
  std::unique_ptr<parallel::TriangulationBase<dim>>
  Discretization<dim>::make_triangulation(const MPI_Comm communicator) const
  {
    // Smoothing keeps one level of difference at vertices and fills
    // unrefined islands; it does not undo a refinement flag on a cell whose
    // neighbours stay coarse (smoothing_on_coarsening would, and a single
    // cell at a singular corner is what the indicators flag first).
    const auto smoothing = typename Triangulation<dim>::MeshSmoothing(
      Triangulation<dim>::smoothing_on_refinement);
    if (is_simplex)
      // Artificial cells: a rank keeps the cells it owns and one layer of
      // ghosts in its DoFHandler's view, as on a p4est mesh.
      return std::make_unique<parallel::shared::Triangulation<dim>>(
        communicator,
        smoothing,
        true,
        parallel::shared::Triangulation<dim>::partition_metis);
    return std::make_unique<parallel::distributed::Triangulation<dim>>(
      communicator,
      smoothing);
  }



  template <int dim>
  std::string
  Discretization<dim>::description() const
  {
    if (is_simplex)
      return dim == 2 ? "P1 on triangles" : "P1 on tetrahedra";
    return dim == 2 ? "Q1 on quadrilaterals" : "Q1 on hexahedra";
  }



  template <int dim>
  Quadrature<dim>
  vertex_quadrature(const ReferenceCell &cell)
  {
    std::vector<Point<dim>> points;
    for (const unsigned int v : cell.vertex_indices())
      points.push_back(cell.template vertex<dim>(v));
    const double volume = cell.volume();
    return Quadrature<dim>(points,
                           std::vector<double>(points.size(),
                                               volume / points.size()));
  }



  template class Discretization<2>;
  template class Discretization<3>;
  template Quadrature<2>
  vertex_quadrature(const ReferenceCell &);
  template Quadrature<3>
  vertex_quadrature(const ReferenceCell &);
} // namespace VPContact
