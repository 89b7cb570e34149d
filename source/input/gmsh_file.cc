// What a Gmsh .msh file holds, read from its bytes without GridIn (see
// gmsh_file.h).
#include <vpcontact/input/gmsh_file.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

namespace VPContact
{
  // Gmsh writes "$MeshFormat" and then "version file-type data-size" on
  // the next line, file-type 1 for a binary file. GridIn reads only
  // ASCII: on binary bytes it stops at the first word it does not know.
  bool
  is_binary_gmsh(const std::string &bytes)
  {
    std::istringstream in(bytes.substr(0, 256));
    std::string        keyword;
    double             version   = 0;
    int                file_type = 0;
    return (in >> keyword) && keyword == "$MeshFormat"
           && (in >> version >> file_type) && file_type != 0;
  }

  // The largest cell dimension of the elements of a Gmsh file: what a
  // file of tetrahedra read for a 2D scene (or one of triangles for a 3D
  // scene) holds, since GridIn's own message lists only the cell types of
  // the scene's dimension. The file is scanned, not read by GridIn as the
  // other dimension: GridIn crashes on some files of the wrong dimension.
  // Format 2 gives each element's type (1 line, 15 point, 2 triangle, 3
  // quadrilateral, 4 tetrahedron, 5 hexahedron, 6 prism, 7 pyramid);
  // format 4 gives each block's entity dimension. 0 where unknown.
  int
  gmsh_cell_dimension(const std::string &bytes)
  {
    std::istringstream in(bytes);
    std::string        word;
    double             version = 0;
    while (in >> word && word != "$MeshFormat")
      ;
    if (!(in >> version))
      return 0;
    while (in >> word && word != "$Elements")
      ;
    int  dimension = 0;
    long n_items   = 0;
    if (version >= 4)
      {
        long n_elements, min_tag, max_tag;
        if (!(in >> n_items >> n_elements >> min_tag >> max_tag))
          return 0;
        for (long block = 0; block < n_items; ++block)
          {
            int  entity_dim, entity_tag, type;
            long n_in_block;
            if (!(in >> entity_dim >> entity_tag >> type >> n_in_block))
              return dimension;
            dimension = std::max(dimension, entity_dim);
            std::string line;
            std::getline(in, line);
            for (long i = 0; i < n_in_block && std::getline(in, line); ++i)
              ;
          }
        return dimension;
      }
    if (!(in >> n_items))
      return 0;
    std::string line;
    std::getline(in, line);
    for (long i = 0; i < n_items && std::getline(in, line); ++i)
      {
        std::istringstream element(line);
        int                number, type;
        if (element >> number >> type)
          dimension = std::max(dimension,
                               type >= 4 && type <= 7 ? 3 :
                               type == 2 || type == 3 ? 2 :
                                                        dimension);
      }
    return dimension;
  }



  namespace
  {
    // The dimension of a Gmsh element type (format 2), -1 if unknown.
    int
    element_type_dimension(const int type)
    {
      switch (type)
        {
          case 15:
            return 0;
          case 1:
          case 8:
            return 1;
          case 2:
          case 3:
          case 9:
          case 10:
          case 16:
            return 2;
          case 4:
          case 5:
          case 6:
          case 7:
          case 11:
          case 12:
          case 17:
            return 3;
          default:
            return -1;
        }
    }



    // Format 2: each element line is "number type n_tags physical ...".
    std::set<int>
    physical_tags_v2(std::istream &in, const int element_dim)
    {
      std::set<int> tags;
      std::string   word;
      while (in >> word && word != "$Elements")
        ;
      long n_elements = 0;
      if (!(in >> n_elements))
        return tags;
      std::string line;
      std::getline(in, line);
      for (long i = 0; i < n_elements && std::getline(in, line); ++i)
        {
          std::istringstream element(line);
          int                number, type, n_tags, physical = 0;
          if ((element >> number >> type >> n_tags)
              && element_type_dimension(type) == element_dim)
            tags.insert(n_tags > 0 && (element >> physical) ? physical : 0);
        }
      return tags;
    }



    // Format 4: the $Entities section gives each entity its physical tags,
    // and each block of $Elements names its entity.
    std::set<int>
    physical_tags_v4(std::istream &in, const int element_dim)
    {
      std::set<int> tags;
      std::string   word;
      while (in >> word && word != "$Entities")
        ;
      long n_entities[4];
      if (!(in >> n_entities[0] >> n_entities[1] >> n_entities[2]
            >> n_entities[3]))
        return tags;
      std::map<int, std::vector<int>> physical_of_entity;
      std::string                     line;
      std::getline(in, line);
      for (int d = 0; d < 4; ++d)
        for (long i = 0; i < n_entities[d] && std::getline(in, line); ++i)
          {
            std::istringstream entity(line);
            int                tag;
            double             coordinate;
            long               n_physical = 0;
            entity >> tag;
            for (int c = 0; c < (d == 0 ? 3 : 6); ++c)
              entity >> coordinate;
            entity >> n_physical;
            for (long p = 0; d == element_dim && p < n_physical; ++p)
              {
                int physical;
                if (entity >> physical)
                  physical_of_entity[tag].push_back(physical);
              }
          }
      while (in >> word && word != "$Elements")
        ;
      long n_blocks, n_elements, min_tag, max_tag;
      if (!(in >> n_blocks >> n_elements >> min_tag >> max_tag))
        return tags;
      for (long block = 0; block < n_blocks; ++block)
        {
          int  entity_dim, entity_tag, type;
          long n_in_block;
          if (!(in >> entity_dim >> entity_tag >> type >> n_in_block))
            break;
          std::getline(in, line);
          for (long i = 0; i < n_in_block && std::getline(in, line); ++i)
            ;
          if (entity_dim == element_dim && n_in_block > 0)
            {
              const auto &physical = physical_of_entity[entity_tag];
              // GridIn takes an entity's first physical tag, 0 if none.
              tags.insert(physical.empty() ? 0 : physical.front());
            }
        }
      return tags;
    }
  } // namespace



  std::set<int>
  gmsh_physical_tags(const std::string &bytes, const int element_dim)
  {
    std::istringstream in(bytes);
    std::string        word;
    double             version = 0;
    while (in >> word && word != "$MeshFormat")
      ;
    if (!(in >> version))
      return {};
    return version >= 4 ? physical_tags_v4(in, element_dim) :
                          physical_tags_v2(in, element_dim);
  }



  template <int dim>
  void
  check_gmsh_boundary_tags(const Triangulation<dim> &coarse,
                           const std::string        &bytes,
                           const std::string        &source)
  {
    const std::set<int> tagged = gmsh_physical_tags(bytes, dim - 1);
    std::map<types::boundary_id, unsigned int> untagged;
    for (const auto &face : coarse.active_face_iterators())
      if (face->at_boundary() && tagged.count(face->boundary_id()) == 0)
        ++untagged[face->boundary_id()];
    if (untagged.empty())
      return;
    std::string tag_list;
    for (const int tag : tagged)
      tag_list += (tag_list.empty() ? "" : ",") + std::to_string(tag);
    const std::string faces = (dim == 2 ? "edges" : "faces");
    AssertThrow(
      false,
      ExcMessage(
        source + ": " + std::to_string(untagged.begin()->second) + " boundary "
        + faces + " of the mesh are in no physical group of "
        + "the file (its boundary elements carry the physical tags {" + tag_list
        + "}). Gmsh writes only the elements of physical groups, "
        + "and deal.II gives a boundary face it does not find there the id "
        + std::to_string(untagged.begin()->first)
        + ", which a condition would then take without a word. Put every "
          "boundary "
        + (dim == 2 ? "curve into a Physical Curve" :
                      "surface into a Physical Surface")
        + " of the .geo file and mesh it again (doc/gmsh.md)."));
  }



  template void
  check_gmsh_boundary_tags<2>(const Triangulation<2> &,
                              const std::string &,
                              const std::string &);
  template void
  check_gmsh_boundary_tags<3>(const Triangulation<3> &,
                              const std::string &,
                              const std::string &);
} // namespace VPContact
