// The command line: help, parameter listing, and running a scene.
#include <vpcontact/app/application.h>
#include <vpcontact/app/exit_agreement.h>
#include <vpcontact/app/mpi_io_choice.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parameter_file.h>
#include <vpcontact/input/parameter_listing.h>
#include <vpcontact/linear_algebra/blas_threads.h>
#include <vpcontact/linear_algebra/petsc_tools.h>
#include <vpcontact/simulator/simulator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <muParser.h>
#include <new>
#include <sstream>
#include <string>

namespace VPContact
{
  namespace
  {
    void
    print_usage(std::ostream &out)
    {
      out << "Usage: vpcontact [--resume] SCENE.prm\n"
             "       vpcontact --print-parameters [2|3]\n"
             "       vpcontact --help\n\n"
             "Runs the quasistatic scene described by SCENE.prm (deal.II "
             "ParameterHandler format)\nand writes its fields (.pvtu/.pvd) and "
             "statistics.csv to Output/Directory.\nRun in parallel with "
             "`mpirun -np N vpcontact SCENE.prm`.\n\n"
             "--resume            continue the run from its newest complete "
             "checkpoint (the same\n                    as Checkpoint/Resume "
             "from checkpoint = true). A run stopped by\n                    "
             "SIGINT, SIGTERM, SIGUSR1 or SIGPIPE writes one and exits with "
             "status 75.\n"
             "--print-parameters  print every parameter with its default, "
             "allowed values and\n                    documentation, as a "
             "valid .prm file (for a 2D or 3D scene).\n";
    }



    // Read "Dimension" alone, skipping the other entries, so that the
    // simulator of the right dimension can then declare and read the rest.
    unsigned int
    read_dimension(const ParameterFile &file, const std::string &filename)
    {
      ParameterHandler   prm;
      std::istringstream text(file.text);
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3));
      prm.parse_input(text, filename, "", true);
      return prm.get_integer("Dimension");
    }



    // Run the scene; the exit status is 0, or
    // exit_status_stopped_for_resume when a signal stopped the run after a
    // checkpoint.
    template <int dim>
    int
    run_scene(const ParameterFile &file,
              const std::string   &filename,
              const bool           resume,
              const MPI_Comm       communicator)
    {
      ParameterHandler   prm;
      std::istringstream text(file.text);
      Simulator<dim>::declare_parameters(prm);
      prm.parse_input(text, filename);
      check_number_ranges(prm);
      if (resume)
        {
          prm.enter_subsection("Checkpoint");
          prm.set("Resume from checkpoint", true);
          prm.leave_subsection();
        }
      const std::string directory
        = std::filesystem::path(filename).parent_path().string();
      Simulator<dim> simulator(prm,
                               directory.empty() ? "." : directory,
                               communicator);
      simulator.run();
      return simulator.stopped_for_resume() ? exit_status_stopped_for_resume :
                                              0;
    }



    template <int dim>
    void
    print_parameters()
    {
      ParameterHandler prm;
      Simulator<dim>::declare_parameters(prm);
      std::cout << "# All parameters of vpcontact for a " << dim
                << "D scene, with their defaults.\n";
      print_parameter_listing(prm, std::cout);
    }



    // PETSc starts inside MPI_InitFinalize and aborts there on options it
    // cannot read, so those are refused before; with no communicator yet,
    // the rank is the one mpirun gives (Open MPI, MPICH).
    int
    report_error_before_mpi(const std::string &message)
    {
      const char *rank = std::getenv("OMPI_COMM_WORLD_RANK");
      if (rank == nullptr)
        rank = std::getenv("PMI_RANK");
      if (rank == nullptr || std::string(rank) == "0")
        std::cerr << "\nError: " << message << "\nStopped; exit status 1."
                  << std::endl;
      return 1;
    }



    // An allocation failed: the memory check before the run (a lower bound)
    // passed, but the run needs more than the process may use. The rank
    // that ran out may be alone with it while the others wait in a
    // collective call; the exit agreement then prints its message, naming
    // the rank, and stops them.
    std::string
    out_of_memory_message(const MPI_Comm communicator)
    {
      return "the run needs more memory than this process may use "
             "(std::bad_alloc on rank "
             + std::to_string(Utilities::MPI::this_mpi_process(communicator))
             + "): the machine's memory, its cgroup limit or the process's "
               "ulimit -v. The mesh is set by Geometry/Subdivisions, "
               "Geometry/Mesh file, Geometry/Global refinements and Mesh "
               "refinement/Number of cycles: use fewer cells, more machines, "
               "or raise the limit.";
    }



    // --resume may stand before or after the scene: it is taken out of
    // @p args, so that the rest of the command line is read without it, and
    // the return value says whether it was there.
    bool
    take_resume_flag(std::vector<std::string> &args)
    {
      const auto resume_flag
        = std::remove(args.begin(), args.end(), std::string("--resume"));
      const bool resume = (resume_flag != args.end());
      args.erase(resume_flag, args.end());
      return resume;
    }



    // ParameterHandler's messages name the file with the path it was given;
    // this shows it relative to the parameter file's folder, as the user
    // wrote it (when @p args is a scene alone).
    std::string
    shorten_paths(std::string message, const std::vector<std::string> &args)
    {
      if (args.size() == 1)
        {
          const std::string folder
            = std::filesystem::path(args[0]).parent_path().string();
          for (std::size_t at;
               !folder.empty()
               && (at = message.find(folder + "/")) != std::string::npos;)
            message.erase(at, folder.size() + 1);
        }
      return message;
    }



    // Do what the command line @p args (without --resume) asks: print the
    // usage or the parameters, or run the scene, and return the exit
    // status. The scene's text goes to @p file as soon as it is read, so
    // that the caller's messages about its lines name the file and line
    // they came from.
    int
    run_command_line(const std::vector<std::string> &args,
                     const bool                      resume,
                     const MPI_Comm                  communicator,
                     ParameterFile                  &file)
    {
      const bool rank_zero
        = Utilities::MPI::this_mpi_process(communicator) == 0;
      AssertThrow(!(resume && args.empty()),
                  ExcMessage("--resume needs the scene to continue: "
                             "vpcontact --resume SCENE.prm."));
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          if (rank_zero)
            print_usage(args.empty() ? std::cerr : std::cout);
          return args.empty() ? 1 : 0;
        }
      if (args[0] == "--print-parameters")
        {
          const std::string dim = (args.size() > 1 ? args[1] : "2");
          AssertThrow(dim == "2" || dim == "3",
                      ExcMessage("--print-parameters takes 2 or 3, not '" + dim
                                 + "'."));
          if (rank_zero)
            (dim == "2" ? print_parameters<2>() : print_parameters<3>());
          return 0;
        }
      AssertThrow(args.size() == 1 && args[0].rfind("--", 0) != 0,
                  ExcMessage("Unexpected arguments. Usage: vpcontact "
                             "SCENE.prm (see vpcontact --help)."));

      const std::string &filename = args[0];
      file                        = read_parameter_file(filename, communicator);
      return (read_dimension(file, filename) == 2 ?
                run_scene<2>(file, filename, resume, communicator) :
                run_scene<3>(file, filename, resume, communicator));
    }



    // run_command_line() with every exception caught: the exit status, and
    // in @p error the message for the user (empty if none).
    int
    run_caught(const std::vector<std::string> &args,
               const bool                      resume,
               const MPI_Comm                  communicator,
               ParameterFile                  &file,
               std::string                    &error)
    {
      try
        {
          return run_command_line(args, resume, communicator, file);
        }
      // A negative or absurd array length is a bad_alloc too, but a fault
      // of the program, not a lack of memory: it must not send the user
      // looking for memory.
      catch (const std::bad_array_new_length &)
        {
          error = "an array of impossible length was requested: this is a "
                  "fault of the program, not a lack of memory. Please report "
                  "it with the parameter file.";
        }
      catch (const std::bad_alloc &)
        {
          error = out_of_memory_message(communicator);
        }
      catch (const std::exception &e)
        {
          error = shorten_paths(file.locate(error_message(e)), args);
        }
      // Exceptions that are not std::exceptions come from the libraries
      // underneath (muParser's, for one); they too end the run with a
      // message rather than in std::terminate.
      catch (const mu::Parser::exception_type &e)
        {
          error
            = "muParser: " + e.GetMsg() + " (expression '" + e.GetExpr() + "')";
        }
      catch (...)
        {
          error = "an unknown exception stopped the program. Please report "
                  "this with the parameter file.";
        }
      // An exception without a message still stops the run.
      if (error.empty())
        error = "the program stopped without a message. Please report this "
                "with the parameter file.";
      return 1;
    }
  } // namespace



  int
  run_application(int argc, char **argv)
  {
    // PETSc starts with MPI and reads PETSC_OPTIONS; its errors are told in
    // one message of the program's (petsc_tools.h).
    if (const std::string problem = petsc_options_problem(); !problem.empty())
      return report_error_before_mpi(problem);
    // deal.II's threads: the cores of the node divided among its ranks
    // (DEAL_II_NUM_THREADS may lower it). The BLAS gets one (see
    // set_blas_threads()), and as many as deal.II's only while a
    // factorization runs (BlasThreads), instead of one per core in every
    // rank.
    //
    // Started without mpirun, Open MPI 4 first launches its runtime daemon
    // (orted) for the single process, about 0.2 s. The program keeps it:
    // without the daemon (OMPI_MCA_ess_singleton_isolated=1) all such
    // processes of a machine share one session directory, and the first
    // to end removes the files that another's MPI-IO (the mesh of a
    // checkpoint) still uses.
    prefer_romio_for_mpi_io();
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
    install_petsc_error_messages();
    set_blas_threads(1);
    const MPI_Comm communicator = MPI_COMM_WORLD;
    // Rank 0's command line for all ranks, as its parameter file: under
    // mpirun in MPMD mode the ranks may be given different ones (--resume
    // on one rank only would take it into a checkpoint search alone).
    std::vector<std::string> args
      = Utilities::MPI::broadcast(communicator,
                                  std::vector<std::string>(argv + 1,
                                                           argv + argc),
                                  0);
    const bool resume = take_resume_flag(args);

    // The scene's text, once read: messages about its lines name the file
    // and line they came from.
    ParameterFile       file;
    const ExitAgreement agreement(communicator);
    std::string         error;
    const int status = run_caught(args, resume, communicator, file, error);
    return agreement.finish(status, error);
  }
} // namespace VPContact



extern "C" int
vpcontact_run_application(int argc, char **argv)
{
  return VPContact::run_application(argc, argv);
}
