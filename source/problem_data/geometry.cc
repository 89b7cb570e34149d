// The section "Geometry": the coarse mesh (generated box or mesh file) and its
// global refinement.
#include <vpcontact/input/gmsh_file.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/mesh_checks.h>
#include <vpcontact/input/rank_zero_input.h>
#include <vpcontact/problem_data/geometry.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <boost/crc.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace VPContact
{
  namespace
  {
    // The default corner and subdivision lists of a box, written for dim.
    std::string
    repeated(const std::string &value, const unsigned int n)
    {
      std::string s = value;
      for (unsigned int i = 1; i < n; ++i)
        s += ", " + value;
      return s;
    }

    // How often every one of @p subdivisions can be halved: the L of
    // Geometry::base_level().
    unsigned int
    common_halvings(const std::vector<unsigned int> &subdivisions)
    {
      unsigned int levels = 0;
      while (std::all_of(subdivisions.begin(),
                         subdivisions.end(),
                         [levels](const unsigned int n) {
                           return n > 0 && n % (2u << levels) == 0;
                         }))
        ++levels;
      return levels;
    }

    // The position of @p p, in the box [lower, upper], on a Z-order
    // (Morton) curve: the bits of its coordinates, scaled to 21-bit
    // integers, interleaved. Points close on the curve are close in space.
    template <int dim>
    std::uint64_t
    z_order(const Point<dim> &p,
            const Point<dim> &lower,
            const Point<dim> &upper)
    {
      std::uint64_t key = 0;
      std::uint64_t coordinate[dim];
      for (unsigned int d = 0; d < dim; ++d)
        coordinate[d] = static_cast<std::uint64_t>(
          (p[d] - lower[d]) / std::max(upper[d] - lower[d], 1e-300)
          * ((1 << 21) - 1));
      for (int bit = 20; bit >= 0; --bit)
        for (unsigned int d = 0; d < dim; ++d)
          key = (key << 1) | ((coordinate[d] >> bit) & 1);
      return key;
    }

    // Copy the coarse mesh @p coarse into @p triangulation with its cells
    // sorted along a Z-order curve through their centres, so that
    // neighbours come close together. A mesh file's cells come in the
    // order of its generator, which may be any; the degrees of freedom are
    // numbered in the order of the cells, and every pass over the cells and
    // every matrix of the run would otherwise jump through memory. The
    // cells are put into a serial mesh first: copy_triangulation() takes
    // its mesh smoothing (none) too, as for the meshes that come unsorted.
    template <int dim>
    void
    copy_in_neighbour_order(const Triangulation<dim> &coarse,
                            Triangulation<dim>       &triangulation)
    {
      auto [vertices, cells, faces]
        = GridTools::get_coarse_mesh_description(coarse);
      const auto box = GridTools::compute_bounding_box(coarse);
      std::vector<std::pair<std::uint64_t, unsigned int>> keys;
      for (const auto &cell : coarse.active_cell_iterators())
        keys.emplace_back(z_order<dim>(cell->center(),
                                       box.get_boundary_points().first,
                                       box.get_boundary_points().second),
                          cell->active_cell_index());
      std::sort(keys.begin(), keys.end());
      std::vector<CellData<dim>> ordered;
      ordered.reserve(cells.size());
      for (const auto &key : keys)
        ordered.push_back(cells[key.second]);
      Triangulation<dim> serial;
      serial.create_triangulation(vertices, ordered, faces);
      triangulation.copy_triangulation(serial);
    }
  } // namespace



  template <int dim>
  void
  Geometry<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Mesh",
                        "box",
                        Patterns::Selection("box|file"),
                        "'box': a rectangle (box in 3D) from the corners and "
                        "subdivisions below, with boundary ids 0 = left "
                        "(x = x0), 1 = right, 2 = bottom, 3 = top (4 = front, "
                        "5 = back in 3D). 'file': the mesh in 'Mesh file'.");
      prm.declare_entry(
        "Cell type",
        "quadrilateral",
        Patterns::Selection("quadrilateral|simplex"),
        "The cells and elements: 'quadrilateral' (hexahedra in 3D) with Q1 "
        "elements, or 'simplex': triangles (tetrahedra) with the paper's P1 "
        "elements, the box's cells split into 2 triangles (5 tetrahedra). A "
        "mesh file's cells are recognised from the file: triangles there "
        "need no entry, and 'simplex' with a file of quadrilaterals is "
        "refused. Simplex meshes are held whole on every rank, partitioned "
        "by METIS, refined only uniformly, and not checkpointed "
        "(doc/simplex.md).");
      prm.declare_entry("Lower corner",
                        repeated("0", dim),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box only: the corner with the smallest coordinates "
                        "[m], dim comma-separated values.");
      prm.declare_entry("Upper corner",
                        repeated("1", dim),
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Box only: the corner with the largest coordinates "
                        "[m], dim comma-separated values.");
      prm.declare_entry("Subdivisions",
                        repeated(dim == 2 ? "32" : "8", dim),
                        Patterns::List(Patterns::Integer(1), dim, dim),
                        "Box only: number of cells in each coordinate "
                        "direction of the coarse mesh, dim values.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::FileName(),
                        "File only: a mesh that deal.II's GridIn reads, chosen "
                        "by extension (.msh Gmsh, .inp UCD, .vtk VTK), with "
                        "boundary ids as physical tags. A relative path is "
                        "relative to the directory of the parameter file.");
      prm.declare_entry("Global refinements",
                        "0",
                        Patterns::Integer(0, 12),
                        "Number of times every coarse cell is refined "
                        "(each refinement halves h).");
    }
    CurvedBoundaries<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }



  template <int dim>
  void
  Geometry<dim>::parse_parameters(ParameterHandler  &prm,
                                  const std::string &parameter_directory,
                                  const MPI_Comm     communicator)
  {
    prm.enter_subsection("Geometry");
    shape = (prm.get("Mesh") == "box" ? Shape::box : Shape::file);

    const auto lower = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Lower corner")));
    const auto upper = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("Upper corner")));
    const auto subs = Utilities::string_to_int(
      Utilities::split_string_list(prm.get("Subdivisions")));
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower_corner[d] = lower[d];
        upper_corner[d] = upper[d];
        VPContactCheckParameter(upper[d] > lower[d],
                                "Geometry/Upper corner",
                                prm.get("Upper corner"),
                                "every coordinate must exceed that of "
                                "Geometry/Lower corner = "
                                  + prm.get("Lower corner") + ".");
      }
    subdivisions.assign(subs.begin(), subs.end());

    mesh_file          = prm.get("Mesh file");
    mesh_file_as_given = mesh_file;
    if (shape == Shape::file)
      {
        VPContactCheckParameter(!mesh_file.empty(),
                                "Geometry/Mesh file",
                                "(empty)",
                                "'Mesh = file' needs a mesh file name.");
        if (std::filesystem::path(mesh_file).is_relative())
          mesh_file = (std::filesystem::path(parameter_directory) / mesh_file)
                        .lexically_normal()
                        .string();
      }
    n_global_refinements = prm.get_integer("Global refinements");
    simplex              = (prm.get("Cell type") == "simplex");
    curved_boundaries.parse_parameters(prm);
    prm.leave_subsection();
    if (shape == Shape::file)
      {
        // The file decides the cell type. It is read here, and the mesh kept
        // for the first create_coarse_mesh().
        read_mesh_bytes(communicator);
        file_mesh = std::make_shared<Triangulation<dim>>();
        read_mesh_file(*file_mesh);
        const bool file_simplex
          = file_mesh->begin_active()->reference_cell().is_simplex();
        VPContactCheckParameter(file_simplex || !simplex,
                                "Geometry/Cell type",
                                "simplex",
                                "the mesh file " + mesh_file_as_given
                                  + " has quadrilaterals (hexahedra); a "
                                    "file's cells decide the element. Remove "
                                    "the entry, or mesh the body with "
                                    "triangles (tetrahedra).");
        simplex = file_simplex;
      }
  }



  template <int dim>
  bool
  Geometry<dim>::simplex_cells() const
  {
    return simplex;
  }



  template <int dim>
  void
  Geometry<dim>::create_mesh(parallel::TriangulationBase<dim> &triangulation)
  {
    create_coarse_mesh(triangulation);
    triangulation.refine_global(base_level() + n_global_refinements);
  }



  template <int dim>
  void
  Geometry<dim>::create_coarse_mesh(
    parallel::TriangulationBase<dim> &triangulation)
  {
    const std::string refinements = " and Geometry/Global refinements = "
                                    + std::to_string(n_global_refinements);
    if (shape == Shape::box)
      {
        // Before the cells exist: a box of 10^12 cells must be refused, not
        // built until memory runs out.
        // (2 triangles or 5 tetrahedra per box cell on simplices).
        double      n_coarse_cells = simplex ? (dim == 2 ? 2 : 5) : 1;
        std::string list;
        for (const unsigned int n : subdivisions)
          {
            n_coarse_cells *= n;
            list += (list.empty() ? "" : ", ") + std::to_string(n);
          }
        check_memory(n_coarse_cells,
                     "Geometry/Subdivisions = " + list + refinements,
                     triangulation.get_communicator());
        if (simplex)
          create_simplex_box(triangulation);
        else
          {
            // The box of Subdivisions, base_level() levels coarser.
            std::vector<unsigned int> coarse(subdivisions);
            for (unsigned int &n : coarse)
              n >>= base_level();
            GridGenerator::subdivided_hyper_rectangle(triangulation,
                                                      coarse,
                                                      lower_corner,
                                                      upper_corner,
                                                      true);
          }
      }
    else
      {
        // The file is read into a serial mesh and its cells are checked
        // there, before the distributed mesh is built from it (p4est fails
        // without a message on a mesh it cannot hold).
        std::shared_ptr<Triangulation<dim>> coarse = std::move(file_mesh);
        if (!coarse)
          {
            coarse = std::make_shared<Triangulation<dim>>();
            read_mesh_file(*coarse);
          }
        check_memory(coarse->n_active_cells(),
                     "Geometry/Mesh file = " + mesh_file_as_given + " ("
                       + std::to_string(coarse->n_active_cells()) + " cells)"
                       + refinements,
                     triangulation.get_communicator());
        if (simplex)
          copy_in_neighbour_order(*coarse, triangulation);
        else
          triangulation.copy_triangulation(*coarse);
      }
    curved_boundaries.attach(triangulation);
  }



  template <int dim>
  void
  Geometry<dim>::check_memory(const double       n_coarse_cells,
                              const std::string &entries,
                              const MPI_Comm     communicator) const
  {
    // A mesh of simplices lives whole on every rank (Discretization): its
    // refined cells count against each rank's memory.
    const double n_cells = n_coarse_cells
                           * std::pow(2., double(dim) * n_global_refinements)
                           * finest_growth;
    check_mesh_memory(dim,
                      n_cells,
                      simplex ? n_cells : n_coarse_cells,
                      simplex,
                      entries
                        + (simplex ? " with Geometry/Cell type = simplex" : "")
                        + growth_entries,
                      communicator);
  }



  template <int dim>
  void
  Geometry<dim>::create_simplex_box(Triangulation<dim> &triangulation) const
  {
    // deal.II 9.4 does not colour a box of simplices: the boundary ids of
    // the box of quadrilaterals are set here from the faces' centres.
    Triangulation<dim> coarse;
    GridGenerator::subdivided_hyper_rectangle_with_simplices(coarse,
                                                             subdivisions,
                                                             lower_corner,
                                                             upper_corner,
                                                             false);
    for (const auto &face : coarse.active_face_iterators())
      if (face->at_boundary())
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double tolerance
              = 1e-10 * (upper_corner[d] - lower_corner[d]);
            if (std::abs(face->center()[d] - lower_corner[d]) < tolerance)
              face->set_boundary_id(2 * d);
            else if (std::abs(face->center()[d] - upper_corner[d]) < tolerance)
              face->set_boundary_id(2 * d + 1);
          }
    triangulation.copy_triangulation(coarse);
  }



  template <int dim>
  void
  Geometry<dim>::read_mesh_bytes(const MPI_Comm communicator)
  {
    // Rank 0 alone reads the file: a rank whose working directory holds
    // another copy, or none, never looks, and a file rank 0 cannot read
    // stops every rank with the same message. The file is checked first:
    // GridIn's own message for a missing file does not say which parameter
    // it came from, and for an extension it does not know it says only
    // "ExcInvalidState".
    const std::string extension
      = std::filesystem::path(mesh_file).extension().string();
    mesh_bytes = read_on_rank_zero(communicator, [&]() {
      std::error_code error;
      VPContactCheckParameter(std::filesystem::is_regular_file(mesh_file, error)
                                && std::ifstream(mesh_file).good(),
                              "Geometry/Mesh file",
                              mesh_file_as_given,
                              "cannot open this file (missing, not a regular "
                              "file, or not readable). Check the path; a "
                              "relative path is taken from the parameter "
                              "file's folder.");
      VPContactCheckParameter(extension == ".msh" || extension == ".inp"
                                || extension == ".ucd" || extension == ".vtk"
                                || extension == ".unv",
                              "Geometry/Mesh file",
                              mesh_file_as_given,
                              "the extension '" + extension
                                + "' is not one of a mesh format this "
                                  "program reads: .msh (Gmsh), .inp or .ucd "
                                  "(UCD), .vtk (VTK legacy), .unv (I-DEAS).");
      return file_bytes(mesh_file,
                        "Geometry/Mesh file = " + mesh_file_as_given);
    });
    VPContactCheckParameter(
      extension != ".msh" || !is_binary_gmsh(mesh_bytes),
      "Geometry/Mesh file",
      mesh_file_as_given,
      "this is a binary Gmsh file, and only ASCII .msh files (format 2 or "
      "4) can be read. Write it as ASCII: 'gmsh "
        + mesh_file_as_given
        + " -save -format msh4 -o ascii.msh' (or -format msh2) converts "
          "it, and 'Mesh.Binary = 0;' in the .geo file (or leaving "
          "'Save in binary format' unchecked on export) writes ASCII.");
  }



  template <int dim>
  void
  Geometry<dim>::read_mesh_file(Triangulation<dim> &coarse) const
  {
    const std::string source = "Geometry/Mesh file = " + mesh_file_as_given;
    // Every rank builds the mesh from the bytes rank 0 read, in the format
    // GridIn would choose from the file name (Gmsh versions 2 and 4 are
    // told apart by GridIn from the file's header).
    const std::string extension
      = std::filesystem::path(mesh_file).extension().string().substr(1);
    GridIn<dim> grid_in;
    grid_in.attach_triangulation(coarse);
    try
      {
        std::istringstream in(mesh_bytes);
        grid_in.read(in, GridIn<dim>::parse_format(extension));
      }
    catch (const std::bad_alloc &)
      {
        AssertThrow(false,
                    ExcMessage(source
                               + ": reading it needs more memory than this "
                                 "machine has (does the file announce more "
                                 "vertices or cells than it holds?)."));
      }
    catch (const std::exception &e)
      {
        constexpr int other_dim = (dim == 2 ? 3 : 2);
        VPContactCheckParameter(
          extension != "msh" || gmsh_cell_dimension(mesh_bytes) != other_dim,
          "Geometry/Mesh file",
          mesh_file_as_given,
          "the file holds " + std::to_string(other_dim) + "D cells ("
            + (dim == 2 ? "tetrahedra or hexahedra" :
                          "triangles or quadrilaterals")
            + "), and the scene is " + std::to_string(dim)
            + "D. Set Dimension = " + std::to_string(other_dim)
            + " at the top of the parameter file, or give a "
            + std::to_string(dim) + "D mesh.");
        AssertThrow(false,
                    ExcMessage(source + ": GridIn could not read it as a "
                               + std::to_string(dim)
                               + "D mesh. Its message was: "
                               + error_message(e)));
      }
    check_mesh_cells(coarse, source);
    if (extension == "msh")
      check_gmsh_boundary_tags(coarse, mesh_bytes, source);
  }



  template <int dim>
  std::string
  Geometry<dim>::mesh_source() const
  {
    return shape == Shape::box ? "" :
                                 "Geometry/Mesh file = " + mesh_file_as_given;
  }



  template <int dim>
  std::string
  Geometry<dim>::mesh_file_checksum() const
  {
    if (shape == Shape::box)
      return "";
    boost::crc_32_type crc;
    crc.process_bytes(mesh_bytes.data(), mesh_bytes.size());
    char text[16];
    std::snprintf(text, sizeof(text), "%08x", crc.checksum());
    return text;
  }



  template <int dim>
  unsigned int
  Geometry<dim>::global_refinements() const
  {
    return n_global_refinements;
  }



  template <int dim>
  unsigned int
  Geometry<dim>::base_level() const
  {
    return shape == Shape::box && !simplex ? common_halvings(subdivisions) : 0;
  }



  template <int dim>
  std::uint64_t
  Geometry<dim>::box_cell_index(const Point<dim> &p) const
  {
    if (base_level() == 0)
      return 0;
    std::uint64_t index = 0;
    for (unsigned int d = dim; d-- > 0;)
      {
        const double relative
          = (p[d] - lower_corner[d]) / (upper_corner[d] - lower_corner[d]);
        const auto i = static_cast<std::uint64_t>(
          std::clamp(std::floor(relative * subdivisions[d]),
                     0.,
                     subdivisions[d] - 1.));
        index = index * subdivisions[d] + i;
      }
    return index;
  }



  template <int dim>
  void
  Geometry<dim>::set_finest_growth(const double       growth,
                                   const std::string &entries)
  {
    finest_growth  = growth;
    growth_entries = entries;
  }



  template <int dim>
  std::set<types::boundary_id>
  Geometry<dim>::boundary_ids_of(
    const parallel::TriangulationBase<dim> &triangulation)
  {
    std::vector<types::boundary_id> local;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            local.push_back(face->boundary_id());
    const auto all
      = Utilities::MPI::compute_set_union(local,
                                          triangulation.get_communicator());
    return std::set<types::boundary_id>(all.begin(), all.end());
  }



  template class Geometry<2>;
  template class Geometry<3>;
} // namespace VPContact
