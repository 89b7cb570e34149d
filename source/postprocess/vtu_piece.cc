// Writing a VtuPiece as a .vtu file, and the cell fields of its .pvtu record.
#include <vpcontact/postprocess/vtu_piece.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <zlib.h>

namespace VPContact
{
  using namespace dealii;

  namespace
  {
    // Base64, as VTK's XML readers decode binary data arrays.
    void
    append_base64(std::string &text, const unsigned char *data, std::size_t n)
    {
      static const char table[]
        = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      text.reserve(text.size() + 4 * ((n + 2) / 3));
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
    }



    /// zlib's stream format of @p size bytes at @p bytes, deflated at the
    /// fastest level with @p strategy, into @p compressed (resized to fit).
    void
    deflate_bytes(const Bytef        *bytes,
                  const uLong         size,
                  const int           strategy,
                  std::vector<Bytef> &compressed)
    {
      z_stream stream{};
      AssertThrow(
        deflateInit2(&stream, Z_BEST_SPEED, Z_DEFLATED, 15, 8, strategy)
          == Z_OK,
        ExcMessage("zlib could not start compressing a field."));
      compressed.resize(deflateBound(&stream, size));
      stream.next_in   = const_cast<Bytef *>(bytes);
      stream.avail_in  = size;
      stream.next_out  = compressed.data();
      stream.avail_out = compressed.size();
      const int status = deflate(&stream, Z_FINISH);
      compressed.resize(stream.total_out);
      deflateEnd(&stream);
      AssertThrow(status == Z_STREAM_END,
                  ExcMessage("zlib could not compress a field."));
    }



    /// The deflate strategy for a field's values. The fields of a step
    /// (displacement, stresses) are floats whose low mantissa bits are
    /// noise: deflate's search for repeated strings finds little there,
    /// and its run-length mode alone (Z_RLE, matches at distance one)
    /// compresses them to within a few per cent of the same size at two to
    /// three times the speed (measured on the fields of the paper scene at
    /// 512^2 cells). Fields of long runs (the damage of sound material, a
    /// contact status) compress many times better with the full search.
    /// The first bytes decide: where the full search halves them, it is
    /// used for the whole array.
    int
    field_strategy(const Bytef *bytes, const uLong size)
    {
      const uLong        sample = std::min<uLong>(size, 16384);
      std::vector<Bytef> compressed;
      deflate_bytes(bytes, sample, Z_DEFAULT_STRATEGY, compressed);
      return (2 * compressed.size() < sample ? Z_DEFAULT_STRATEGY : Z_RLE);
    }



    // One data array in VTK's compressed binary form, as deal.II's
    // write_vtu() gives it, appended to @p text: the header (number of
    // blocks, block size, size of the last block, compressed size of each
    // block, as UInt32) and the compressed bytes, each encoded on its own.
    // An empty array has no text (VTK reads no values for it). The geometry
    // and the cells are deflated with the full search (their values repeat
    // in patterns); a field (@p is_field) as field_strategy() finds.
    template <typename T>
    void
    append_array(std::string          &text,
                 const std::string    &attributes,
                 const std::vector<T> &values,
                 const bool            is_field = false)
    {
      text += "    <DataArray " + attributes + " format=\"binary\">\n";
      if (!values.empty())
        {
          const auto *bytes = reinterpret_cast<const Bytef *>(values.data());
          const uLong size  = values.size() * sizeof(T);
          AssertThrow(size <= std::numeric_limits<std::uint32_t>::max(),
                      ExcMessage("A field of a .vtu piece exceeds the 4 GB "
                                 "of VTK's 32-bit block header: run on more "
                                 "MPI ranks."));
          std::vector<Bytef> compressed;
          deflate_bytes(bytes,
                        size,
                        (is_field ? field_strategy(bytes, size) :
                                    Z_DEFAULT_STRATEGY),
                        compressed);
          const std::uint32_t header[4]
            = {1,
               static_cast<std::uint32_t>(size),
               static_cast<std::uint32_t>(size),
               static_cast<std::uint32_t>(compressed.size())};
          // Room for all that follows at once: a text that grows by
          // doubling would take twice the array's text for a moment.
          text.reserve(text.size() + 4 * ((sizeof(header) + 2) / 3)
                       + 4 * ((compressed.size() + 2) / 3) + 32);
          append_base64(text,
                        reinterpret_cast<const unsigned char *>(header),
                        sizeof(header));
          append_base64(text, compressed.data(), compressed.size());
          text += '\n';
        }
      text += "    </DataArray>\n";
    }



    // The array, and its memory given back once it is in @p text.
    template <typename T>
    void
    move_array(std::string       &text,
               const std::string &attributes,
               std::vector<T>    &values)
    {
      append_array(text, attributes, values);
      std::vector<T>().swap(values);
    }



    // The <Points> and <Cells> sections of a piece: the tags to @p emit,
    // each array to @p add (appended to a text, or written at once).
    template <typename Emit,
              typename Add,
              typename Points,
              typename Indices,
              typename Types>
    void
    points_and_cells(const Emit &emit,
                     const Add  &add,
                     Points     &points,
                     Indices    &connectivity,
                     Indices    &offsets,
                     Types      &types)
    {
      emit("  <Points>\n");
      add("type=\"Float32\" NumberOfComponents=\"3\"", points);
      emit("  </Points>\n  <Cells>\n");
      add("type=\"Int32\" Name=\"connectivity\"", connectivity);
      add("type=\"Int32\" Name=\"offsets\"", offsets);
      add("type=\"UInt8\" Name=\"types\"", types);
      emit("  </Cells>\n");
    }



    void
    write_fields(std::ostream &out, const std::vector<VtuPiece::Field> &fields)
    {
      for (const auto &field : fields)
        {
          std::string text;
          append_array(text,
                       "type=\"Float32\" Name=\"" + field.name + "\""
                         + (field.n_components > 1 ?
                              " NumberOfComponents=\""
                                + std::to_string(field.n_components) + "\"" :
                              std::string()),
                       field.values,
                       true);
          out << text;
        }
    }
  } // namespace



  std::size_t
  VtuPiece::n_points() const
  {
    return sections_of_mesh ? n_points_of_mesh : points.size() / 3;
  }



  std::size_t
  VtuPiece::n_cells() const
  {
    return sections_of_mesh ? n_cells_of_mesh : types.size();
  }



  std::uint64_t
  VtuPiece::mesh_fingerprint() const
  {
    // FNV-1a's step over 64-bit words (the bytes of each array, its size
    // first), each product folded by a shift: a product carries a bit only
    // upwards, so that without the fold two changes in the high bits of
    // the words could cancel. A few milliseconds for the millions of
    // points of a large piece.
    std::uint64_t hash = 14695981039346656037ull;
    const auto    add  = [&hash](const std::uint64_t word) {
      hash = (hash ^ word) * 1099511628211ull;
      hash ^= hash >> 29;
    };
    const auto add_array = [&add](const void *data, const std::size_t size) {
      add(size);
      const auto *bytes = static_cast<const unsigned char *>(data);
      std::size_t i     = 0;
      for (; i + 8 <= size; i += 8)
        {
          std::uint64_t word;
          std::memcpy(&word, bytes + i, 8);
          add(word);
        }
      for (; i < size; ++i)
        add(bytes[i]);
    };
    add_array(points.data(), points.size() * sizeof(float));
    add_array(connectivity.data(), connectivity.size() * sizeof(std::int32_t));
    add_array(offsets.data(), offsets.size() * sizeof(std::int32_t));
    add_array(types.data(), types.size());
    return hash;
  }



  std::string
  VtuPiece::mesh_sections() const
  {
    std::string text;
    points_and_cells([&text](const char *tags) { text += tags; },
                     [&text](const std::string &attributes,
                             const auto        &values) {
                       append_array(text, attributes, values);
                     },
                     points,
                     connectivity,
                     offsets,
                     types);
    return text;
  }



  std::shared_ptr<const std::string>
  VtuPiece::take_mesh_sections()
  {
    // Each array is freed as soon as it is in the text, so that the
    // sections take hardly more memory to make than they free.
    const std::size_t n_points_here = n_points(), n_cells_here = n_cells();
    std::string       text;
    points_and_cells([&text](const char *tags) { text += tags; },
                     [&text](const std::string &attributes, auto &values) {
                       move_array(text, attributes, values);
                     },
                     points,
                     connectivity,
                     offsets,
                     types);
    text.shrink_to_fit();
    auto sections    = std::make_shared<const std::string>(std::move(text));
    sections_of_mesh = sections;
    n_points_of_mesh = n_points_here;
    n_cells_of_mesh  = n_cells_here;
    return sections;
  }



  void
  VtuPiece::reuse_mesh_sections(std::shared_ptr<const std::string> sections)
  {
    n_points_of_mesh = n_points();
    n_cells_of_mesh  = n_cells();
    sections_of_mesh = std::move(sections);
    std::vector<float>().swap(points);
    std::vector<std::int32_t>().swap(connectivity);
    std::vector<std::int32_t>().swap(offsets);
    std::vector<std::uint8_t>().swap(types);
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
        << n_cells() << "\">\n";
    // Without kept sections, array by array, so that only one array's
    // text exists at a time.
    if (sections_of_mesh)
      out << *sections_of_mesh;
    else
      points_and_cells([&out](const char *tags) { out << tags; },
                       [&out](const std::string &attributes,
                              const auto        &values) {
                         std::string text;
                         append_array(text, attributes, values);
                         out << text;
                       },
                       points,
                       connectivity,
                       offsets,
                       types);
    out << "  <PointData>\n";
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
