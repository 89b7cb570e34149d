// Snapshots of a run's solution, their file format, and the errors of
// Theorem 2 between a run and a reference on nested meshes.
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/rank_zero_input.h>
#include <vpcontact/postprocess/output_writer.h>
#include <vpcontact/postprocess/reference_solution.h>

#include <deal.II/base/quadrature_lib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace VPContact
{
  namespace
  {
    // Offsets of the four fields inside a cell's values.
    template <int dim>
    struct Layout
    {
      static constexpr unsigned int V            = Snapshot<dim>::n_vertices;
      static constexpr unsigned int vertices     = 0;
      static constexpr unsigned int displacement = V * dim;
      static constexpr unsigned int damage       = 2 * V * dim;
      static constexpr unsigned int stress       = 2 * V * dim + V;
    };

    const std::string magic = "vpcontact-snapshot-1";
  } // namespace



  template <int dim>
  void
  Snapshot<dim>::add_cell(
    const CellId                                          &id,
    const std::array<Point<dim>, n_vertices>              &vertices,
    const std::array<Tensor<1, dim>, n_vertices>          &u,
    const std::array<double, n_vertices>                  &zeta,
    const std::array<SymmetricTensor<2, dim>, n_vertices> &sigma)
  {
    ids.push_back(id.template to_binary<dim>());
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int d = 0; d < dim; ++d)
        values.push_back(vertices[v][d]);
    for (unsigned int v = 0; v < n_vertices; ++v)
      for (unsigned int d = 0; d < dim; ++d)
        values.push_back(u[v][d]);
    for (unsigned int v = 0; v < n_vertices; ++v)
      values.push_back(has_damage ? zeta[v] : 1.);
    for (unsigned int q = 0; q < n_vertices; ++q)
      for (unsigned int c = 0; c < n_stress; ++c)
        values.push_back(sigma[q].access_raw_entry(c));
  }



  template <int dim>
  unsigned int
  Snapshot<dim>::n_cells() const
  {
    return ids.size();
  }



  template <int dim>
  const CellId::binary_type &
  Snapshot<dim>::id(const unsigned int cell) const
  {
    return ids[cell];
  }



  template <int dim>
  Point<dim>
  Snapshot<dim>::vertex(const unsigned int cell, const unsigned int v) const
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = values[cell * n_values + Layout<dim>::vertices + v * dim + d];
    return p;
  }



  template <int dim>
  Tensor<1, dim>
  Snapshot<dim>::displacement(const unsigned int cell,
                              const unsigned int v) const
  {
    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = values[cell * n_values + Layout<dim>::displacement + v * dim + d];
    return u;
  }



  template <int dim>
  double
  Snapshot<dim>::damage(const unsigned int cell, const unsigned int v) const
  {
    return values[cell * n_values + Layout<dim>::damage + v];
  }



  template <int dim>
  SymmetricTensor<2, dim>
  Snapshot<dim>::stress(const unsigned int cell, const unsigned int q) const
  {
    SymmetricTensor<2, dim> sigma;
    for (unsigned int c = 0; c < n_stress; ++c)
      sigma.access_raw_entry(c)
        = values[cell * n_values + Layout<dim>::stress + q * n_stress + c];
    return sigma;
  }



  template <int dim>
  void
  Snapshot<dim>::append(const Snapshot<dim> &other)
  {
    ids.insert(ids.end(), other.ids.begin(), other.ids.end());
    values.insert(values.end(), other.values.begin(), other.values.end());
  }



  template <int dim>
  std::vector<char>
  Snapshot<dim>::to_bytes() const
  {
    // Header: magic, dim, damage flag, time, number of cells; then the ids
    // and the values as raw arrays (the byte order of the machine).
    std::vector<char> bytes(magic.begin(), magic.end());
    auto              put = [&bytes](const void *data, const std::size_t size) {
      const char *begin = static_cast<const char *>(data);
      bytes.insert(bytes.end(), begin, begin + size);
    };
    const std::uint32_t header[3] = {static_cast<std::uint32_t>(dim),
                                     static_cast<std::uint32_t>(has_damage),
                                     static_cast<std::uint32_t>(ids.size())};
    put(header, sizeof(header));
    put(&time, sizeof(time));
    put(ids.data(), ids.size() * sizeof(CellId::binary_type));
    put(values.data(), values.size() * sizeof(double));
    return bytes;
  }



  template <int dim>
  Snapshot<dim>
  Snapshot<dim>::from_bytes(const std::vector<char> &bytes,
                            const std::string       &source)
  {
    std::size_t position = 0;
    auto        get      = [&](void *data, const std::size_t size) {
      AssertThrow(position + size <= bytes.size(),
                  ExcMessage("The reference snapshot " + source
                             + " is truncated. Write the reference again."));
      std::memcpy(data, bytes.data() + position, size);
      position += size;
    };
    std::string head(magic.size(), ' ');
    get(head.data(), magic.size());
    AssertThrow(head == magic,
                ExcMessage(source
                           + " is not a vpcontact snapshot (written by "
                             "Reference solution/Write snapshots)."));
    std::uint32_t header[3];
    get(header, sizeof(header));
    AssertThrow(header[0] == dim,
                ExcMessage("The reference snapshot " + source + " is "
                           + std::to_string(header[0]) + "D, this run is "
                           + std::to_string(dim) + "D."));
    Snapshot<dim> snapshot;
    snapshot.has_damage = (header[1] != 0);
    get(&snapshot.time, sizeof(double));
    snapshot.ids.resize(header[2]);
    get(snapshot.ids.data(), header[2] * sizeof(CellId::binary_type));
    snapshot.values.resize(std::size_t(header[2]) * n_values);
    get(snapshot.values.data(), snapshot.values.size() * sizeof(double));
    AssertThrow(position == bytes.size(),
                ExcMessage("The reference snapshot " + source
                           + " has trailing data. Write the reference again."));
    return snapshot;
  }



  template class Snapshot<2>;
  template class Snapshot<3>;



  void
  ReferenceSolution::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference solution");
    {
      prm.declare_entry(
        "Write snapshots",
        "false",
        Patterns::Bool(),
        "Store this run as a reference for convergence studies: the "
        "displacement, stress and damage at every Snapshot interval, cell by "
        "cell, in Output/Directory/reference/ (in the last cycle's mesh when "
        "there are several cycles). Run it on a mesh and step finer than "
        "those of the runs it will judge.");
      prm.declare_entry("Snapshot interval",
                        "0.05",
                        Patterns::Double(0),
                        "Time between two snapshots [s]; a multiple of the "
                        "time step. 0: every step. Runs compared with the "
                        "reference are compared at these times where they "
                        "have a step.");
      prm.declare_entry(
        "Compare with",
        "",
        Patterns::Anything(),
        "The reference/ folder written by another run (Write snapshots). "
        "When given, every run (every cycle) is compared with it at every "
        "common time in the norms of the paper's Theorem 2: ||eps(u - "
        "u_h)||, ||sigma - sigma_h|| and ||zeta - zeta_h|| (L2), and the "
        "errors go to statistics.csv and the convergence table. The "
        "reference must be on a refinement of the same coarse mesh, at "
        "least as fine everywhere. A relative path is relative to the "
        "working directory.");
    }
    prm.leave_subsection();
  }



  void
  ReferenceSolution::parse_parameters(ParameterHandler  &prm,
                                      const std::string &output_directory)
  {
    prm.enter_subsection("Reference solution");
    write_snapshots = prm.get_bool("Write snapshots");
    interval        = prm.get_double("Snapshot interval");
    compare_folder  = prm.get("Compare with");
    prm.leave_subsection();
    write_folder = output_directory + "/reference";
    std::error_code error;
    VPContactCheckParameter(
      !(write_snapshots && !compare_folder.empty()
        && std::filesystem::equivalent(compare_folder, write_folder, error)),
      "Reference solution/Compare with",
      compare_folder,
      "this run would compare with the snapshots it is "
      "writing itself. Give another run's folder.");
  }



  bool
  ReferenceSolution::writes_snapshots() const
  {
    return write_snapshots;
  }



  bool
  ReferenceSolution::compares() const
  {
    return !compare_folder.empty();
  }



  void
  ReferenceSolution::check_time_step(const double k,
                                     const double end_time) const
  {
    if (!write_snapshots || interval == 0.)
      return;
    const double ratio = interval / k;
    VPContactCheckParameter(std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio
                              && ratio >= 0.5 && interval <= end_time,
                            "Reference solution/Snapshot interval",
                            interval,
                            "the interval must be a whole number of time "
                            "steps (k = "
                              + to_text(k) + ") and at most the end time.");
  }



  bool
  ReferenceSolution::is_snapshot_step(const unsigned int n,
                                      const double       k) const
  {
    if (interval == 0.)
      return true;
    const unsigned int every
      = static_cast<unsigned int>(std::llround(interval / k));
    return n % every == 0;
  }



  template <int dim>
  void
  ReferenceSolution::write(const Snapshot<dim> &local,
                           const MPI_Comm       communicator)
  {
    // Gather the cells on rank 0, which writes the file and then the index
    // (both atomically: a reader sees complete snapshots only). If rank 0
    // cannot write, every rank stops with its message instead of waiting for
    // it in the next collective call.
    const auto pieces = Utilities::MPI::gather(communicator, local.to_bytes());
    write_on_rank_zero(communicator, [&]() {
      Snapshot<dim> all;
      all.time       = local.time;
      all.has_damage = local.has_damage;
      for (unsigned int r = 0; r < pieces.size(); ++r)
        all.append(Snapshot<dim>::from_bytes(pieces[r], "(rank data)"));

      if (written.empty())
        {
          std::error_code error;
          std::filesystem::create_directories(write_folder, error);
          AssertThrow(!error,
                      ExcMessage("Reference solution/Write snapshots: cannot "
                                 "create the folder "
                                 + write_folder + " (" + error.message()
                                 + "). Check Output/Directory."));
        }
      const std::string name
        = "snapshot-" + Utilities::int_to_string(written.size(), 5) + ".bin";
      const auto bytes = all.to_bytes();
      write_file_atomically(write_folder + "/" + name,
                            std::string(bytes.begin(), bytes.end()));
      written.emplace_back(local.time, name);

      std::ostringstream text;
      text << "# vpcontact reference: time, snapshot file\n"
           << std::setprecision(17);
      for (const auto &[t, file] : written)
        text << t << ' ' << file << '\n';
      write_file_atomically(write_folder + "/reference.index", text.str());
    });
  }



  void
  ReferenceSolution::read_index(const MPI_Comm communicator)
  {
    // Rank 0 reads the index (and the snapshots, in read()) and hands it to
    // every rank: all compare at the same times, and a file that rank 0
    // cannot read stops all ranks together.
    const std::string  filename = compare_folder + "/reference.index";
    std::istringstream in(read_on_rank_zero(communicator, [&]() {
      AssertThrow(std::ifstream(filename).good(),
                  ExcMessage("Reference solution/Compare with = "
                             + compare_folder + ": cannot read " + filename
                             + ". Run the reference scene first (Reference "
                               "solution/Write snapshots = true writes it "
                               "into its Output/Directory/reference)."));
      return file_bytes(filename, filename);
    }));
    index.clear();
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line[0] != '#')
        {
          std::istringstream fields(line);
          double             t;
          std::string        file;
          AssertThrow(fields >> t >> file,
                      ExcMessage("Malformed line in " + filename + ": '" + line
                                 + "'. Write the reference again."));
          index.emplace_back(t, file);
        }
    AssertThrow(!index.empty(),
                ExcMessage(filename
                           + " lists no snapshot. Run the reference "
                             "scene to its end."));
    time_tolerance = 1e-9 * std::max(1., std::abs(index.back().first));
  }



  bool
  ReferenceSolution::has_time(const double t) const
  {
    for (const auto &entry : index)
      if (std::abs(entry.first - t) <= time_tolerance)
        return true;
    return false;
  }



  void
  ReferenceSolution::check_common_times(
    const double                           k,
    const unsigned int                     n_steps,
    const std::function<double(unsigned)> &time,
    const std::string                     &k_entry) const
  {
    // A snapshot time t > 0 is a time of the run if it is t_n for the n
    // nearest to t / k.
    unsigned int common = 0;
    for (const auto &entry : index)
      {
        const double n = std::round(entry.first / k);
        if (entry.first > time_tolerance && n >= 1 && n <= n_steps
            && std::abs(time(static_cast<unsigned int>(n)) - entry.first)
                 <= time_tolerance)
          ++common;
      }
    VPContactCheckParameter(
      common >= 2,
      "Reference solution/Compare with",
      compare_folder,
      "the reference's " + std::to_string(index.size()) + " snapshots (t = "
        + to_text(index.front().first) + " to " + to_text(index.back().first)
        + ", set by its Reference solution/Snapshot interval and Time/End "
          "time) and the steps of this run ("
        + k_entry + ", Time/End time = " + to_text(time(n_steps)) + ") share "
        + std::to_string(common)
        + " time(s) after t = 0; errors, orders and effectivities need at "
          "least two. Write the reference with a Snapshot interval that "
          "is a multiple of this run's time step and an End time of at "
          "least this run's, or choose this run's Time/Time step and End "
          "time to meet the reference's snapshot times.");
  }



  template <int dim>
  Snapshot<dim>
  ReferenceSolution::read(const double t, const MPI_Comm communicator) const
  {
    for (const auto &[time, file] : index)
      if (std::abs(time - t) <= time_tolerance)
        {
          const std::string filename = compare_folder + "/" + file;
          const std::string bytes    = read_on_rank_zero(communicator, [&]() {
            AssertThrow(std::ifstream(filename).good(),
                        ExcMessage("Cannot read the reference snapshot "
                                   + filename + " listed in its index."));
            return file_bytes(filename, filename);
          });
          return Snapshot<dim>::from_bytes(std::vector<char>(bytes.begin(),
                                                             bytes.end()),
                                           filename);
        }
    AssertThrow(false,
                ExcMessage("No reference snapshot at t = " + to_text(t)));
    return {};
  }



  const std::string &
  ReferenceSolution::comparison_folder() const
  {
    return compare_folder;
  }



  template void
  ReferenceSolution::write(const Snapshot<2> &, const MPI_Comm);
  template void
  ReferenceSolution::write(const Snapshot<3> &, const MPI_Comm);
  template Snapshot<2>
  ReferenceSolution::read(const double, const MPI_Comm) const;
  template Snapshot<3>
  ReferenceSolution::read(const double, const MPI_Comm) const;
} // namespace VPContact
