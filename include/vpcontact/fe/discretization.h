// The cell type of the mesh and what follows from it: the finite element, the
// quadrature rules, and the kind of distributed triangulation that holds it.
#ifndef vpcontact_discretization_h
#define vpcontact_discretization_h

#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/reference_cell.h>

#include <memory>
#include <string>

namespace VPContact
{
  using namespace dealii;

  /**
   * The discretization of one run, chosen by the cell type of its mesh.
   *
   * Quadrilaterals (hexahedra): Q1 in every component, the 2^dim-point Gauss
   * rule for assembly and the stress history, and a
   * parallel::distributed::Triangulation (p4est), which refines adaptively
   * and writes checkpoints.
   *
   * Triangles (tetrahedra): the paper's own element, P1 (FE_SimplexP) in
   * every component, and the one-point rule at the centroid, so that the
   * stress history is the paper's space Q^h of piecewise constant stresses
   * (the strain of a P1 function is constant on a cell and the stiffness
   * matrix is exact). p4est holds only quadrilaterals and hexahedra, so the
   * mesh lives in a parallel::shared::Triangulation partitioned by METIS:
   * every rank stores all cells and owns a METIS part of them. deal.II 9.4
   * refines simplices only globally (no hanging nodes).
   *
   * On both, the lumped (nodal) mass uses the vertex rule and the faces a
   * Gauss rule exact for the products of two shape functions; the mapping is
   * get_default_linear_mapping() of the triangulation (MappingQ1, or
   * MappingFE with P1 on simplices).
   */
  template <int dim>
  class Discretization
  {
  public:
    /// @p with_damage: a damage component after the dim displacement ones.
    Discretization(const bool simplex, const bool with_damage);

    /// Whether the cells are triangles (tetrahedra).
    bool
    simplex() const;

    /// The element of the run: dim displacement components and possibly
    /// the damage, all of one scalar element.
    const FESystem<dim> &
    finite_element() const;

    /// The rule of assembly, stress storage and stress output.
    const Quadrature<dim> &
    quadrature() const;

    /// The linear mapping of the cells: MappingQ1, or MappingFE with P1.
    const Mapping<dim> &
    mapping() const;

    /// A rule on faces, exact for products of two shape functions.
    const Quadrature<dim - 1> &
    face_quadrature() const;

    /// An empty triangulation of the kind that holds this cell type.
    std::unique_ptr<parallel::TriangulationBase<dim>>
    make_triangulation(const MPI_Comm communicator) const;

    /// "Q1 on quadrilaterals", "P1 on tetrahedra", ... for the screen.
    std::string
    description() const;

  private:
    const bool                is_simplex;
    const FESystem<dim>       fe;
    const Quadrature<dim>     cell_rule;
    const Quadrature<dim - 1> face_rule;
  };

  /**
   * The vertex (trapezoidal) rule of @p cell: the vertices of the reference
   * cell with equal weights. With linear elements it gives the lumped mass,
   * diagonal because every shape function vanishes at all vertices but one
   * (QGaussLobatto(2) on quadrilaterals; deal.II's nodal rule of a simplex
   * has no weights).
   */
  template <int dim>
  Quadrature<dim>
  vertex_quadrature(const ReferenceCell &cell);
} // namespace VPContact

#endif
