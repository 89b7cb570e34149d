// The cell fields of a .vtu piece as VTK cell data (see vtu_cell_data.h).
#include <vpcontact/postprocess/vtu_cell_data.h>

#include <deal.II/base/exceptions.h>

#include <cstdint>
#include <zlib.h>

namespace VPContact
{
  namespace
  {
    // Base64, as VTK's XML readers decode binary data arrays.
    std::string
    base64(const unsigned char *data, const std::size_t n)
    {
      static const char table[]
        = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::string out;
      out.reserve(4 * ((n + 2) / 3));
      for (std::size_t i = 0; i < n; i += 3)
        {
          const std::uint32_t b
            = (std::uint32_t(data[i]) << 16)
              | (i + 1 < n ? std::uint32_t(data[i + 1]) << 8 : 0)
              | (i + 2 < n ? std::uint32_t(data[i + 2]) : 0);
          out += table[(b >> 18) & 63];
          out += table[(b >> 12) & 63];
          out += i + 1 < n ? table[(b >> 6) & 63] : '=';
          out += i + 2 < n ? table[b & 63] : '=';
        }
      return out;
    }



    // One data array in VTK's compressed binary form: the header (number
    // of blocks, block size, size of the last block, compressed size of
    // each block) and the compressed bytes, each encoded on its own.
    std::string
    compressed_array(const std::vector<float> &values)
    {
      const auto        *bytes = reinterpret_cast<const Bytef *>(values.data());
      const uLong        size  = values.size() * sizeof(float);
      uLongf             compressed_size = compressBound(size);
      std::vector<Bytef> compressed(compressed_size);
      AssertThrow(compress2(compressed.data(),
                            &compressed_size,
                            bytes,
                            size,
                            Z_BEST_SPEED)
                    == Z_OK,
                  ExcMessage("zlib could not compress a cell field."));
      const std::uint32_t header[4]
        = {1,
           static_cast<std::uint32_t>(size),
           static_cast<std::uint32_t>(size),
           static_cast<std::uint32_t>(compressed_size)};
      return base64(reinterpret_cast<const unsigned char *>(header),
                    sizeof(header))
             + base64(compressed.data(), compressed_size);
    }
  } // namespace



  template <int dim>
  std::string
  take_cell_data(std::vector<DataOutBase::Patch<dim, dim>> &patches,
                 const std::vector<std::string>            &names)
  {
    if (names.empty() || patches.empty())
      return "";
    const unsigned int n_rows  = patches[0].data.n_rows();
    const unsigned int n_point = n_rows - names.size();
    std::string        xml     = "    <CellData>\n";
    std::vector<float> values(patches.size());
    for (unsigned int f = 0; f < names.size(); ++f)
      {
        for (std::size_t p = 0; p < patches.size(); ++p)
          values[p] = patches[p].data(n_point + f, 0);
        xml += "    <DataArray type=\"Float32\" Name=\"" + names[f]
               + "\" format=\"binary\">\n" + compressed_array(values)
               + "\n    </DataArray>\n";
      }
    xml += "    </CellData>\n";
    // The point fields alone stay in the patches. They are the first rows,
    // and a table stores its rows one after the other, so that dropping
    // the last rows keeps them where they are: no copy, and no allocation
    // per cell.
    for (auto &patch : patches)
      patch.data.reinit(TableIndices<2>(n_point, patch.data.n_cols()),
                        /*omit_default_initialization=*/true);
    return xml;
  }



  void
  write_with_cell_data(std::ostream      &out,
                       const std::string &vtu,
                       const std::string &cell_data)
  {
    // In pieces, without a second copy of the piece in memory.
    const auto end = vtu.rfind("</Piece>");
    AssertThrow(end != std::string::npos,
                ExcMessage("A .vtu piece without </Piece>."));
    out.write(vtu.data(), end);
    out << cell_data;
    out.write(vtu.data() + end, vtu.size() - end);
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



  template std::string
  take_cell_data<2>(std::vector<DataOutBase::Patch<2, 2>> &,
                    const std::vector<std::string> &);
  template std::string
  take_cell_data<3>(std::vector<DataOutBase::Patch<3, 3>> &,
                    const std::vector<std::string> &);
} // namespace VPContact
