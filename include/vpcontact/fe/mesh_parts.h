// The connected parts of a distributed mesh: pieces that share no node with
// each other are separate bodies, and each must be held on its own.
#ifndef vpcontact_mesh_parts_h
#define vpcontact_mesh_parts_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The connected components of the mesh of a DoFHandler, two cells being
   * connected when they share a degree of freedom (a node): the pieces the
   * discretization couples. Each rank labels the degrees of freedom of its
   * owned and ghost cells by union-find; the labels, the smallest global
   * index of a component, then travel between ranks through the ghost
   * layer until no rank lowers one (as many rounds as a part crosses rank
   * boundaries). Parts are numbered in the order of their labels, which
   * does not depend on the number of ranks. Collective.
   */
  template <int dim>
  class MeshParts
  {
  public:
    explicit MeshParts(const DoFHandler<dim> &dof_handler);

    unsigned int
    n_parts() const;

    /// The part of a degree of freedom on an owned or ghost cell.
    unsigned int
    part_of(const types::global_dof_index dof) const;

    /// Its number of cells (all ranks).
    types::global_cell_index
    n_cells(const unsigned int part) const;

    /// The corners of its bounding box (all ranks).
    std::pair<Point<dim>, Point<dim>>
    bounding_box(const unsigned int part) const;

    /// The ids of its boundary faces (all ranks).
    const std::set<types::boundary_id> &
    boundary_ids(const unsigned int part) const;

    /// "the part of N cells between (a) and (b), boundary ids ..." for
    /// messages.
    std::string
    description(const unsigned int part) const;

  private:
    /// Label every locally relevant dof with its component's smallest
    /// global dof index (all ranks agree).
    void
    label_components(const DoFHandler<dim> &dof_handler);

    /// Cell counts, bounding boxes and boundary ids of the parts.
    void
    measure_parts(const DoFHandler<dim> &dof_handler);

    IndexSet                                       relevant;
    std::vector<types::global_dof_index>           labels; // by relevant index
    std::vector<types::global_dof_index>           part_labels;
    std::vector<types::global_cell_index>          cells;
    std::vector<std::pair<Point<dim>, Point<dim>>> boxes;
    std::vector<std::set<types::boundary_id>>      ids;
  };
} // namespace VPContact

#endif
