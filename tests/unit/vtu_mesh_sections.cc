// Unit test: FieldWriter keeps the compressed points and cells of a piece
// written at once (VtuPiece::mesh_sections()) and writes the next piece of the
// same mesh with them. A piece written with the sections of another piece of
// its mesh is the same file as written alone, and frees its own points and
// cells; a piece of another mesh, or with two coordinates of another sign, has
// another fingerprint. Then three outputs of two fields on one mesh of two
// quadrilaterals and one on a mesh whose cells differ in one vertex, through a
// FieldWriter in the background and at once: every file is byte for byte the
// file VtuPiece::write() gives its piece alone.
#include <vpcontact/postprocess/field_writer.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace VPContact;

namespace
{
  // Two unit squares side by side, a point field and a cell field that
  // depend on @p step; with @p other_mesh the second cell's last vertex
  // moves to the first cell's.
  FieldPiece
  piece_of_step(const unsigned int step, const bool other_mesh)
  {
    FieldPiece fields;
    VtuPiece  &piece   = fields.piece;
    piece.points       = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
    piece.connectivity = {0, 1, 4, 3, 1, 2, 5, other_mesh ? 3 : 4};
    piece.offsets      = {4, 8};
    piece.types        = {9, 9};
    VtuPiece::Field zeta{"zeta", 1, {}};
    for (unsigned int p = 0; p < 6; ++p)
      zeta.values.push_back(0.1f * p + step);
    piece.point_fields.push_back(zeta);
    piece.cell_fields.push_back({"von_mises", 1, {1.5f * step, 2.5f * step}});
    fields.names      = {"zeta"};
    fields.cell_names = {"von_mises"};
    return fields;
  }

  std::string
  content_of(const std::string &filename)
  {
    std::ifstream      in(filename, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void
  check(const bool in_background, const std::string &folder)
  {
    FieldWriter writer;
    for (unsigned int step = 0; step < 4; ++step)
      {
        const bool         other_mesh = (step == 3);
        std::ostringstream alone;
        piece_of_step(step, other_mesh).piece.write(alone);
        FieldPiece        fields   = piece_of_step(step, other_mesh);
        const std::string filename = folder + "/piece_" + std::to_string(step);
        writer.start(std::move(fields), filename, in_background);
        const std::string problem = writer.wait();
        std::cout << (in_background ? "background" : "at once") << ", output "
                  << step << (other_mesh ? " (other mesh)" : "") << ": "
                  << (problem.empty() ? "written" : problem)
                  << "; the file of the piece alone: "
                  << (content_of(filename) == alone.str() ? "yes" : "no")
                  << std::endl;
      }
  }

  // The piece level: fingerprints, and a piece written with the sections
  // of another piece of its mesh.
  void
  check_reuse()
  {
    const FieldPiece first = piece_of_step(0, false);
    FieldPiece       next  = piece_of_step(1, false);
    const FieldPiece other = piece_of_step(1, true);
    std::cout << "same mesh, same fingerprint: "
              << (first.piece.mesh_fingerprint()
                      == next.piece.mesh_fingerprint() ?
                    "yes" :
                    "no")
              << "; other mesh, other fingerprint: "
              << (other.piece.mesh_fingerprint()
                      != next.piece.mesh_fingerprint() ?
                    "yes" :
                    "no")
              << std::endl;
    // Two changes in the highest bit of a 64-bit word (the signs of the
    // second float of the first two words), which a plain FNV-1a step over
    // words would let cancel.
    FieldPiece signs = piece_of_step(0, false);
    signs.piece.points[1] *= -1.f;
    signs.piece.points[3] *= -1.f;
    std::cout << "two signs flipped, other fingerprint: "
              << (signs.piece.mesh_fingerprint()
                      != first.piece.mesh_fingerprint() ?
                    "yes" :
                    "no")
              << std::endl;
    std::ostringstream alone, reused;
    next.piece.write(alone);
    next.piece.reuse_mesh_sections(
      std::make_shared<const std::string>(first.piece.mesh_sections()));
    next.piece.write(reused);
    std::cout << "written with the first piece's sections: "
              << (reused.str() == alone.str() ? "the same file" : "differs")
              << "; its own points and cells freed: "
              << (next.piece.points.empty() && next.piece.connectivity.empty() ?
                    "yes" :
                    "no")
              << "; " << next.piece.n_points() << " points, "
              << next.piece.n_cells() << " cells" << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 2);
  const std::string                folder = "vtu_mesh_sections_files";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directory(folder);
  check_reuse();
  check(true, folder);
  check(false, folder);
  std::filesystem::remove_all(folder);
}
