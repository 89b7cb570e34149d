// Cell quantities (the stress of a cell, the rank that owns it) written as
// VTK cell data: deal.II 9.4 writes every field of a .vtu file as point data,
// on the duplicated vertices of each cell, where ParaView cannot colour by
// cells. These functions take the cell fields out of the patches and write
// them as a <CellData> section of the piece and of its .pvtu record.
#ifndef vpcontact_vtu_cell_data_h
#define vpcontact_vtu_cell_data_h

#include <deal.II/base/data_out_base.h>

#include <ostream>
#include <string>
#include <vector>

namespace VPContact
{
  using namespace dealii;

  /**
   * The <CellData> section of a .vtu piece for the fields @p names, which
   * are the last names.size() data rows of every patch of @p patches (one
   * patch per cell, the field constant on it), in the binary
   * zlib-compressed encoding that deal.II's write_vtu() gives the file
   * (header type UInt32, one block). Then those rows are removed from the
   * patches, so that write_vtu() writes the point fields alone.
   */
  template <int dim>
  std::string
  take_cell_data(std::vector<DataOutBase::Patch<dim, dim>> &patches,
                 const std::vector<std::string>            &names);

  /// Write @p vtu, a piece written by write_vtu(), to @p out with
  /// @p cell_data inserted into its <Piece>.
  void
  write_with_cell_data(std::ostream      &out,
                       const std::string &vtu,
                       const std::string &cell_data);

  /// @p pvtu, a record written by write_pvtu_record(), with a <PCellData>
  /// section naming the cell fields @p names.
  std::string
  insert_cell_data_record(const std::string              &pvtu,
                          const std::vector<std::string> &names);
} // namespace VPContact

#endif
