// One .vtu piece of a field output: the rank's cells, each vertex once, the
// fields at the vertices and on the cells, in VTK's XML format (binary,
// zlib-compressed), and the <PCellData> section of its .pvtu record.
#ifndef vpcontact_vtu_piece_h
#define vpcontact_vtu_piece_h

#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace VPContact
{
  /**
   * The data of one VTK UnstructuredGrid piece of linear cells. Unlike
   * deal.II's DataOut, which writes every cell as a patch of its own (each
   * vertex once per cell that has it), a piece lists each vertex of the
   * rank's cells once: the fields of this program are P1/Q1, continuous, so
   * that a vertex has one value, and the piece is a quarter of the points
   * in 2D (an eighth in 3D), with no FEValues on the cells to build it.
   */
  struct VtuPiece
  {
    /// One field: its name, its number of components (1, or 3 for a
    /// vector, as VTK reads vectors) and its values, one tuple of
    /// n_components per point or per cell.
    struct Field
    {
      std::string        name;
      unsigned int       n_components = 1;
      std::vector<float> values;
    };

    /// x, y, z of every point (z = 0 in 2D).
    std::vector<float> points;
    /// The points of each cell in VTK's order, one cell after the other;
    /// offsets[c] is where cell c ends.
    std::vector<std::int32_t> connectivity;
    std::vector<std::int32_t> offsets;
    /// VTK's cell types (VTK_QUAD, VTK_HEXAHEDRON, VTK_TRIANGLE, VTK_TETRA).
    std::vector<std::uint8_t> types;

    std::vector<Field> point_fields;
    std::vector<Field> cell_fields;

    /// The number of points and of cells.
    std::size_t
    n_points() const;
    std::size_t
    n_cells() const;

    /// A 64-bit hash of the points and the cells, which tells whether the
    /// mesh_sections() of another piece can stand for this one's.
    std::uint64_t
    mesh_fingerprint() const;

    /// The <Points> and <Cells> sections of the piece, compressed and
    /// encoded as write() writes them.
    std::string
    mesh_sections() const;

    /// The same, kept by this piece for write(), its points and cells
    /// freed one array after the other as they are compressed.
    std::shared_ptr<const std::string>
    take_mesh_sections();

    /**
     * Write @p sections, the mesh_sections() of a piece of the same points
     * and cells, instead of compressing the points and cells again, and
     * free them here: on a mesh that stays, every field output has the
     * same sections (FieldWriter keeps them).
     */
    void
    reuse_mesh_sections(std::shared_ptr<const std::string> sections);

    /// Whether reuse_mesh_sections() gave the sections.
    bool
    has_mesh_sections() const
    {
      return sections_of_mesh != nullptr;
    }

    /**
     * Write the piece to @p out as a whole .vtu file: every array in
     * binary form, compressed by zlib at its fastest level (the level
     * deal.II's VtkFlags::best_speed gives; the fields of a time step are
     * written many times in a run, and the better levels cost several times
     * the time for a few per cent of the size). A field whose first bytes
     * do not compress to half is deflated in zlib's run-length mode, two
     * to three times faster for noisy floats (see vtu_piece.cc).
     */
    void
    write(std::ostream &out) const;

  private:
    std::shared_ptr<const std::string> sections_of_mesh;
    std::size_t                        n_points_of_mesh = 0;
    std::size_t                        n_cells_of_mesh  = 0;
  };

  /// @p pvtu, a record written by deal.II's write_pvtu_record(), with a
  /// <PCellData> section naming the cell fields @p names.
  std::string
  insert_cell_data_record(const std::string              &pvtu,
                          const std::vector<std::string> &names);
} // namespace VPContact

#endif
