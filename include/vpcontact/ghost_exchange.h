// Copies an owned Trilinos vector into a ghosted one (its owned and ghost
// entries) with one Epetra_Import kept for as long as the layouts stay.
#ifndef vpcontact_ghost_exchange_h
#define vpcontact_ghost_exchange_h

#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_Import.h>
#include <memory>

namespace VPContact
{
  using namespace dealii;

  /**
   * ghosted = owned, for vectors of the same global size, the first with
   * ghost entries.
   *
   * Why not deal.II's assignment: in deal.II 9.4 it builds a new
   * Epetra_Import on every call, even on one rank (where the ghosted layout
   * lists the same indices as the owned one but is not recognized as the
   * same), and building it walks every index of both layouts with a hash
   * lookup each. The simulator copies the displacement and the damage into
   * their ghosted vectors several times per step. Here the import is built
   * once and reused while both vectors keep their layouts (checked on every
   * call by the address of the layout data, which a vector keeps until it
   * is reinitialized; a new address costs one full comparison); where the two
   * layouts are the same, the values are copied directly.
   */
  class GhostExchange
  {
  public:
    void
    copy(const TrilinosWrappers::MPI::Vector &owned,
         TrilinosWrappers::MPI::Vector       &ghosted);

  private:
    /// Copies of the two layouts of the last call (they keep the layout
    /// data alive, so that the same data pointer means the same layout),
    /// whether they are the same, and the import between them if not.
    std::unique_ptr<Epetra_BlockMap> source_layout;
    std::unique_ptr<Epetra_BlockMap> target_layout;
    bool                             same_layouts = false;
    std::unique_ptr<Epetra_Import>   importer;
  };
} // namespace VPContact

#endif
