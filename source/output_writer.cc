// The section "Output" and the files of a run: fields, time series, table.
#include <vpcontact/input_error.h>
#include <vpcontact/output_writer.h>

#include <deal.II/base/utilities.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace VPContact
{
  void
  write_file_atomically(const std::string &filename, const std::string &content)
  {
    const std::string temporary = filename + ".tmp";
    {
      std::ofstream out(temporary);
      out << content;
      out.close();
      AssertThrow(out.good(),
                  ExcMessage("Cannot write the file " + temporary
                             + " (disk full or no permission?). The previous "
                               "version of "
                             + filename + " is left as it was."));
    }
    std::error_code error;
    std::filesystem::rename(temporary, filename, error);
    AssertThrow(!error,
                ExcMessage("Cannot rename " + temporary + " to " + filename
                           + ": " + error.message()));
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
    prm.leave_subsection();
    VPContactCheckParameter(!output_directory.empty(),
                            "Output/Directory",
                            "(empty)",
                            "give a folder name, e.g. 'results'.");
    base_directory_name = output_directory;
  }



  template <int dim>
  void
  OutputWriter<dim>::prepare_directory(const MPI_Comm communicator) const
  {
    // Only rank 0 touches the file system here; the verdict is broadcast so
    // that every rank stops together, with the same message.
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(output_directory, error);
        if (error)
          problem = "cannot create this folder (" + error.message() + ")";
        else
          {
            const std::string probe = output_directory + "/.write_test";
            std::ofstream     out(probe);
            out << "probe\n";
            out.close();
            if (!out.good())
              problem = "cannot write into this folder";
            std::filesystem::remove(probe, error);
          }
      }
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    VPContactCheckParameter(problem.empty(),
                            "Output/Directory",
                            output_directory,
                            problem
                              + ". Give a folder that can be created "
                                "and written.");
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
  OutputWriter<dim>::write_fields(const DataOut<dim> &data_out,
                                  const unsigned int  n,
                                  const double        time,
                                  const MPI_Comm      communicator)
  {
    const std::string pvtu
      = data_out.write_vtu_with_pvtu_record(output_directory + "/",
                                            "solution",
                                            n,
                                            communicator,
                                            5);
    times_and_names.emplace_back(time, pvtu);
    write_pvd_record(communicator);
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
    return times_and_names;
  }



  template <int dim>
  void
  OutputWriter<dim>::restore_field_outputs(
    const std::vector<std::pair<double, std::string>> &outputs,
    const MPI_Comm                                     communicator)
  {
    times_and_names = outputs;
    if (!times_and_names.empty())
      write_pvd_record(communicator);
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
    output_directory
      = (subfolder.empty() ? base_directory_name :
                             base_directory_name + "/" + subfolder);
    times_and_names.clear();
  }



  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace VPContact
