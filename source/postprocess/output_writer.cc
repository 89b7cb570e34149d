// The section "Output" and the files of a run: fields, time series, table.
#include <vpcontact/input/input_error.h>
#include <vpcontact/postprocess/output_writer.h>
#include <vpcontact/postprocess/resumed_field_outputs.h>
#include <vpcontact/postprocess/vtu_piece.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <boost/serialization/utility.hpp>
#include <climits>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

namespace VPContact
{
  namespace
  {
    // The longest path this program writes below an output folder
    // (e.g. checkpoint.new/.vpcontact-checkpoint.tmp) is shorter than this.
    constexpr std::size_t longest_inner_path = 64;

    // A value of a few thousand characters, shortened for a message.
    std::string
    abbreviated(const std::string &value)
    {
      if (value.size() <= 80)
        return value;
      return value.substr(0, 40) + "..." + value.substr(value.size() - 20)
             + " (" + std::to_string(value.size()) + " characters)";
    }

  } // namespace



  void
  write_file_atomically(const std::string &filename, const std::string &content)
  {
    write_file_atomically(filename,
                          [&content](std::ostream &out) { out << content; });
  }



  void
  write_file_atomically(const std::string                         &filename,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = filename + ".tmp";
    {
      std::ofstream   out(temporary);
      std::error_code ignored;
      try
        {
          write(out);
          out.close();
        }
      catch (...)
        {
          // The half-written temporary file is this program's own; the
          // error that stopped the write is the one to report.
          out.close();
          std::filesystem::remove(temporary, ignored);
          throw;
        }
      if (!out.good())
        {
          std::filesystem::remove(temporary, ignored);
          AssertThrow(false,
                      ExcMessage("Cannot write the file " + temporary
                                 + " (disk full or no permission?). The "
                                   "previous version of "
                                 + filename + " is left as it was."));
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, filename, error);
    AssertThrow(!error,
                ExcMessage("Cannot rename " + temporary + " to " + filename
                           + ": " + error.message()));
  }



  void
  write_folder_marker(const std::string &folder, const std::string &marker)
  {
    if (!has_folder_marker(folder, marker))
      write_file_atomically(folder + "/" + marker,
                            "This folder was made by vpcontact, which may "
                            "replace or remove the files it wrote here.\n");
  }



  bool
  has_folder_marker(const std::string &folder, const std::string &marker)
  {
    std::error_code error;
    return std::filesystem::is_regular_file(folder + "/" + marker, error);
  }



  std::string
  problem_on_rank_zero(const MPI_Comm               communicator,
                       const std::function<void()> &task)
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          task();
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          problem = Utilities::trim(info.str());
        }
      catch (const std::exception &e)
        {
          problem = e.what();
        }
    return Utilities::MPI::broadcast(communicator, problem, 0);
  }



  void
  write_on_rank_zero(const MPI_Comm               communicator,
                     const std::function<void()> &write)
  {
    // Only rank 0 writes, but every rank must stop if it fails: the others
    // would otherwise wait for it in the next collective call for ever.
    const std::string problem = problem_on_rank_zero(communicator, write);
    AssertThrow(problem.empty(), ExcMessage(problem));
  }



  template <int dim>
  void
  OutputWriter<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory",
                        "results",
                        Patterns::DirectoryName(),
                        "Folder for the .pvtu/.vtu fields, the .pvd time "
                        "series and statistics.csv, created if missing. A "
                        "relative path is relative to the working directory. "
                        "Files of an earlier run in it are overwritten.");
      prm.declare_entry("Output every",
                        "10",
                        Patterns::Integer(0),
                        "Write fields at step 0, every this many steps and at "
                        "the last step; 0 writes no fields (statistics.csv is "
                        "always written).");
      prm.declare_entry("Deterministic screen output",
                        "false",
                        Patterns::Bool(),
                        "Leave iteration counts and timings out of the screen "
                        "output (they stay in statistics.csv), so that it "
                        "depends only on the discrete solution and not on the "
                        "number of MPI ranks or the machine. The test suite "
                        "uses this.");
      prm.declare_entry("Report solve floor",
                        "false",
                        Patterns::Bool(),
                        "At the end, time one solve of the displacement "
                        "system with everything reused and print it: the "
                        "floor of a time step, for scripts/bench.");
      prm.declare_entry("Write fields in background",
                        "true",
                        Patterns::Bool(),
                        "Compress and write the .vtu files of a field output "
                        "in a task of their own while the next steps are "
                        "computed, where the rank has several threads "
                        "(on a rank of one thread, as with one MPI rank per "
                        "core, they are written at once). "
                        "The .pvtu and .pvd records list an output once its "
                        "files are complete. false writes them before the "
                        "next step starts.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  OutputWriter<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    output_every     = prm.get_integer("Output every");
    deterministic    = prm.get_bool("Deterministic screen output");
    solve_floor      = prm.get_bool("Report solve floor");
    in_background    = prm.get_bool("Write fields in background");
    prm.leave_subsection();
    // The .pvtu records say nothing of the compression; the pieces are
    // compressed at zlib's fastest level, noisy fields in its run-length
    // mode (VtuPiece::write()).
    vtk_flags.compression_level = DataOutBase::VtkFlags::best_speed;
    VPContactCheckParameter(!output_directory.empty(),
                            "Output/Directory",
                            "(empty)",
                            "give a folder name, e.g. 'results'.");
    check_path_length("Output/Directory", output_directory);
    base_directory_name = output_directory;
  }



  template <int dim>
  void
  OutputWriter<dim>::prepare_directory(const MPI_Comm communicator)
  {
    // Only rank 0 touches the file system here; every rank gets its
    // verdict, so that all stop together, with the same message.
    const std::string problem = problem_on_rank_zero(communicator, [&]() {
      const std::vector<std::string> foreign = foreign_outputs();
      std::string                    names;
      for (unsigned int i = 0; i < foreign.size() && i < 5; ++i)
        names += (i > 0 ? ", " : "") + foreign[i];
      AssertThrow(foreign.empty(),
                  ExcMessage("this folder holds files or folders that this "
                             "run would replace ("
                             + names + (foreign.size() > 5 ? ", ..." : "")
                             + ") and that vpcontact did not write (the "
                               "folder has no "
                             + output_folder_marker
                             + " file). Choose another folder, or move them "
                               "away."));
      std::error_code error;
      std::filesystem::create_directories(output_directory, error);
      AssertThrow(!error,
                  ExcMessage("cannot create this folder (" + error.message()
                             + "). Give a folder that can be created and "
                               "written."));
      // The folder is this run's from here to its end, before anything is
      // written into it.
      lock = std::make_unique<FolderLock>(output_directory + "/"
                                            + output_folder_lock,
                                          "this folder");
      if (!lock->note().empty())
        std::cerr << "Note: " << lock->note() << std::endl;
      // The marker doubles as the test that the folder can be written.
      write_folder_marker(output_directory, output_folder_marker);
    });
    AssertThrow(problem.empty(),
                ExcMessage(parameter_message("Output/Directory",
                                             output_directory,
                                             problem)));
    check_seen_by_all_ranks(communicator);
  }



  template <int dim>
  void
  OutputWriter<dim>::check_seen_by_all_ranks(const MPI_Comm communicator) const
  {
    // Every rank writes its own piece of the fields into the folder, which
    // rank 0 has just made: a rank that does not see it (started in another
    // working directory, or on a machine without the file system) would
    // write its pieces where the .pvtu records do not look.
    if (output_every == 0)
      return;
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int blind
      = Utilities::MPI::min(has_folder_marker(output_directory,
                                              output_folder_marker) ?
                              n_ranks :
                              Utilities::MPI::this_mpi_process(communicator),
                            communicator);
    VPContactCheckParameter(
      blind == n_ranks,
      "Output/Directory",
      output_directory,
      "MPI rank " + std::to_string(blind)
        + " does not see this folder, which rank 0 made, and could not "
          "write its part of the fields there. Start all ranks in one "
          "working directory on a file system they share, or give an "
          "absolute path there.");
  }



  template <int dim>
  std::vector<std::string>
  OutputWriter<dim>::foreign_outputs() const
  {
    // The names this program writes into an output folder.
    const auto is_output_name = [](const std::string &name) {
      for (const std::string prefix : {"solution_", "cycle-", "checkpoint"})
        if (name.rfind(prefix, 0) == 0)
          return true;
      for (const std::string file :
           {"statistics.csv", "convergence.csv", "solution.pvd", "reference"})
        if (name == file || name == file + ".tmp")
          return true;
      return false;
    };
    std::vector<std::string> names;
    std::error_code          error;
    if (!std::filesystem::is_directory(output_directory, error)
        || has_folder_marker(output_directory, output_folder_marker))
      return names;
    for (const auto &entry :
         std::filesystem::directory_iterator(output_directory, error))
      if (is_output_name(entry.path().filename().string()))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }



  template <int dim>
  bool
  OutputWriter<dim>::writes_fields_at(const unsigned int n,
                                      const unsigned int n_steps) const
  {
    return output_every > 0 && (n % output_every == 0 || n == n_steps);
  }



  template <int dim>
  void
  OutputWriter<dim>::write_fields(FieldPiece       &&fields,
                                  const unsigned int n,
                                  const double       time,
                                  const bool         steps_follow,
                                  const MPI_Comm     communicator)
  {
    finish_field_output(communicator);

    // The names deal.II's write_vtu_with_pvtu_record() gives: one piece
    // per rank, solution_NNNNN.R.vtu, and the record solution_NNNNN.pvtu.
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int rank_digits = Utilities::needed_digits(n_ranks - 1);
    const std::string  stem = "solution_" + Utilities::int_to_string(n, 5);
    PendingOutput      output;
    output.rank = Utilities::MPI::this_mpi_process(communicator);
    output.time = time;
    output.pvtu = stem + ".pvtu";
    for (unsigned int r = 0; r < n_ranks; ++r)
      output.pieces.push_back(
        stem + "." + Utilities::int_to_string(r, rank_digits) + ".vtu");
    const std::string own_piece = output.pieces[output.rank];

    output.names         = fields.names;
    output.vector_ranges = fields.vector_ranges;
    output.cell_names    = fields.cell_names;
    pending_output       = std::move(output);
    // A rank of one thread (several ranks, one per core) has no idle core
    // for the write: a writer thread beside the steps would take the
    // rank's own core from them, while the other ranks wait for it in
    // every reduction, so that the write would cost the run more than
    // writing at once, all ranks together.
    const bool background
      = in_background && steps_follow && MultithreadInfo::n_threads() > 1;
    field_writer.start(std::move(fields),
                       output_directory + "/" + own_piece,
                       background);
    if (!background)
      finish_field_output(communicator);
  }



  template <int dim>
  void
  OutputWriter<dim>::finish_field_output(const MPI_Comm communicator)
  {
    if (!pending_output)
      return;
    // Every rank learns whether any piece failed, and all stop together.
    const std::vector<std::string> problems
      = Utilities::MPI::all_gather(communicator, field_writer.wait());
    const PendingOutput output = std::move(*pending_output);
    pending_output.reset();
    for (const auto &problem : problems)
      AssertThrow(problem.empty(), ExcMessage(problem));

    write_on_rank_zero(communicator, [&]() { write_pvtu_record(output); });
    times_and_names.emplace_back(output.time, output.pvtu);
    write_pvd_record(communicator);
  }



  template <int dim>
  void
  OutputWriter<dim>::finish_field_output_after_error() noexcept
  {
    if (!pending_output)
      return;
    const PendingOutput output = std::move(*pending_output);
    pending_output.reset();
    const bool written = field_writer.wait().empty();
    if (written && output.rank == 0)
      try
        {
          write_pvtu_record(output);
          times_and_names.emplace_back(output.time, output.pvtu);
          std::ostringstream pvd;
          DataOutBase::write_pvd_record(pvd, times_and_names);
          write_file_atomically(output_directory + "/solution.pvd", pvd.str());
        }
      catch (...)
        {
          // The error that stopped the run is the one to report.
        }
  }



  template <int dim>
  void
  OutputWriter<dim>::write_pvtu_record(const PendingOutput &output) const
  {
    std::ostringstream pvtu;
    DataOutBase::write_pvtu_record(pvtu,
                                   output.pieces,
                                   output.names,
                                   output.vector_ranges,
                                   vtk_flags);
    write_file_atomically(output_directory + "/" + output.pvtu,
                          insert_cell_data_record(pvtu.str(),
                                                  output.cell_names));
  }



  template <int dim>
  void
  OutputWriter<dim>::write_pvd_record(const MPI_Comm communicator) const
  {
    write_on_rank_zero(communicator, [&]() {
      std::ostringstream pvd;
      DataOutBase::write_pvd_record(pvd, times_and_names);
      write_file_atomically(output_directory + "/solution.pvd", pvd.str());
    });
  }



  template <int dim>
  const std::vector<std::pair<double, std::string>> &
  OutputWriter<dim>::field_outputs() const
  {
    Assert(!pending_output,
           ExcMessage("finish_field_output() first: the last output is not "
                      "in the records yet"));
    return times_and_names;
  }



  template <int dim>
  std::string
  OutputWriter<dim>::restore_field_outputs(const FieldOutputRecord &outputs,
                                           const std::string       &folder,
                                           const MPI_Comm communicator)
  {
    // The record must list files of this folder, and only complete ones.
    std::pair<FieldOutputRecord, std::string> kept;
    const std::string problem = problem_on_rank_zero(communicator, [&]() {
      kept = bring_field_outputs(outputs, folder, output_directory);
    });
    AssertThrow(problem.empty(),
                ExcMessage(parameter_message("Output/Directory",
                                             output_directory,
                                             problem)));
    kept            = Utilities::MPI::broadcast(communicator, kept, 0);
    times_and_names = kept.first;
    if (!outputs.empty())
      write_pvd_record(communicator);
    return kept.second;
  }



  template <int dim>
  void
  OutputWriter<dim>::write_statistics(const Statistics &statistics,
                                      const MPI_Comm    communicator) const
  {
    write_on_rank_zero(communicator, [&]() {
      write_file_atomically(output_directory + "/statistics.csv",
                            statistics.to_csv());
    });
  }



  template <int dim>
  bool
  OutputWriter<dim>::deterministic_screen_output() const
  {
    return deterministic;
  }



  template <int dim>
  bool
  OutputWriter<dim>::report_solve_floor() const
  {
    return solve_floor;
  }



  template <int dim>
  const std::string &
  OutputWriter<dim>::directory() const
  {
    return output_directory;
  }



  template <int dim>
  const std::string &
  OutputWriter<dim>::base_directory() const
  {
    return base_directory_name;
  }



  template <int dim>
  void
  OutputWriter<dim>::set_subfolder(const std::string &subfolder)
  {
    Assert(!pending_output,
           ExcMessage("finish_field_output() before a new time series"));
    output_directory
      = (subfolder.empty() ? base_directory_name :
                             base_directory_name + "/" + subfolder);
    times_and_names.clear();
  }



  void
  check_path_length(const std::string &entry, const std::string &folder)
  {
    // PATH_MAX counts the terminating NUL.
    const std::size_t limit = PATH_MAX - 1;
    AssertThrow(folder.size() + longest_inner_path <= limit,
                ExcMessage(parameter_message(
                  entry,
                  abbreviated(folder),
                  "the files the run writes in this folder have paths of "
                  "up to "
                    + std::to_string(longest_inner_path)
                    + " characters more (e.g. "
                      "checkpoint.new/mesh_fixed.data), beyond the "
                      "system's limit of "
                    + std::to_string(limit)
                    + " characters for a path (PATH_MAX). Give a path of at "
                      "most "
                    + std::to_string(limit - longest_inner_path)
                    + " characters: a relative path, or a symbolic link to "
                      "the folder, is shorter.")));
  }



  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace VPContact
