// Writing a VtuPiece as a .vtu file, and the cell fields of its .pvtu record.
#include <vpcontact/postprocess/vtu_piece.h>

#include <deal.II/base/exceptions.h>

#include <cstdint>
#include <limits>
#include <zlib.h>

namespace VPContact
{
  using namespace dealii;

  namespace
  {
    // Base64, as VTK's XML readers decode binary data arrays.
    void
    write_base64(std::ostream &out, const unsigned char *data, std::size_t n)
    {
      static const char table[]
        = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::string text;
      text.reserve(4 * ((n + 2) / 3));
      for (std::size_t i = 0; i < n; i += 3)
        {
          const std::uint32_t b
            = (std::uint32_t(data[i]) << 16)
              | (i + 1 < n ? std::uint32_t(data[i + 1]) << 8 : 0)
              | (i + 2 < n ? std::uint32_t(data[i + 2]) : 0);
          text += table[(b >> 18) & 63];
          text += table[(b >> 12) & 63];
          text += i + 1 < n ? table[(b >> 6) & 63] : '=';
          text += i + 2 < n ? table[b & 63] : '=';
        }
      out << text;
    }



    // One data array in VTK's compressed binary form, as deal.II's
    // write_vtu() gives it: the header (number of blocks, block size, size
    // of the last block, compressed size of each block, as UInt32) and the
    // compressed bytes, each encoded on its own. An empty array has no
    // text (VTK reads no values for it).
    template <typename T>
    void
    write_array(std::ostream         &out,
                const std::string    &attributes,
                const std::vector<T> &values)
    {
      out << "    <DataArray " << attributes << " format=\"binary\">\n";
      if (!values.empty())
        {
          const auto *bytes = reinterpret_cast<const Bytef *>(values.data());
          const uLong size  = values.size() * sizeof(T);
          AssertThrow(size <= std::numeric_limits<std::uint32_t>::max(),
                      ExcMessage("A field of a .vtu piece exceeds the 4 GB "
                                 "of VTK's 32-bit block header: run on more "
                                 "MPI ranks."));
          uLongf             compressed_size = compressBound(size);
          std::vector<Bytef> compressed(compressed_size);
          AssertThrow(compress2(compressed.data(),
                                &compressed_size,
                                bytes,
                                size,
                                Z_BEST_SPEED)
                        == Z_OK,
                      ExcMessage("zlib could not compress a field."));
          const std::uint32_t header[4]
            = {1,
               static_cast<std::uint32_t>(size),
               static_cast<std::uint32_t>(size),
               static_cast<std::uint32_t>(compressed_size)};
          write_base64(out,
                       reinterpret_cast<const unsigned char *>(header),
                       sizeof(header));
          write_base64(out, compressed.data(), compressed_size);
          out << '\n';
        }
      out << "    </DataArray>\n";
    }



    void
    write_fields(std::ostream &out, const std::vector<VtuPiece::Field> &fields)
    {
      for (const auto &field : fields)
        write_array(out,
                    "type=\"Float32\" Name=\"" + field.name + "\""
                      + (field.n_components > 1 ?
                           " NumberOfComponents=\""
                             + std::to_string(field.n_components) + "\"" :
                           std::string()),
                    field.values);
    }
  } // namespace



  std::size_t
  VtuPiece::n_points() const
  {
    return points.size() / 3;
  }



  std::size_t
  VtuPiece::n_cells() const
  {
    return types.size();
  }



  void
  VtuPiece::write(std::ostream &out) const
  {
    out << "<?xml version=\"1.0\"?>\n"
        << "<!-- vpcontact field output -->\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
           "compressor=\"vtkZLibDataCompressor\" "
           "byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n"
        << "<Piece NumberOfPoints=\"" << n_points() << "\" NumberOfCells=\""
        << n_cells() << "\">\n"
        << "  <Points>\n";
    write_array(out, "type=\"Float32\" NumberOfComponents=\"3\"", points);
    out << "  </Points>\n  <Cells>\n";
    write_array(out, "type=\"Int32\" Name=\"connectivity\"", connectivity);
    write_array(out, "type=\"Int32\" Name=\"offsets\"", offsets);
    write_array(out, "type=\"UInt8\" Name=\"types\"", types);
    out << "  </Cells>\n  <PointData>\n";
    write_fields(out, point_fields);
    out << "  </PointData>\n  <CellData>\n";
    write_fields(out, cell_fields);
    out << "  </CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  }



  std::string
  insert_cell_data_record(const std::string              &pvtu,
                          const std::vector<std::string> &names)
  {
    if (names.empty())
      return pvtu;
    std::string section = "    <PCellData>\n";
    for (const auto &name : names)
      section += "      <PDataArray type=\"Float32\" Name=\"" + name
                 + "\" format=\"ascii\"/>\n";
    section += "    </PCellData>\n";
    const auto points = pvtu.find("<PPoints>");
    AssertThrow(points != std::string::npos,
                ExcMessage("A .pvtu record without <PPoints>."));
    const auto line = pvtu.rfind('\n', points) + 1;
    return pvtu.substr(0, line) + section + pvtu.substr(line);
  }
} // namespace VPContact
