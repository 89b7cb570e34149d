// Helpers for the checkpoint tests: the small scene they run, a run whose
// screen output goes to a file and which receives SIGTERM at a chosen step,
// and reading a checkpoint's fields back for comparison.
#ifndef vpcontact_tests_checkpoint_runner_h
#define vpcontact_tests_checkpoint_runner_h

#include <vpcontact/checkpoint/checkpoint_fields.h>
#include <vpcontact/linear_algebra/linear_algebra.h>
#include <vpcontact/problem_data/geometry.h>
#include <vpcontact/simulator/simulator.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <csignal>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace VPContact
{
  /**
   * The paper scene (prm/paper_fig1.prm) with all its history: on an 8 x 8
   * mesh, 20 steps of 0.02, a friction bound of 20 so that the contact
   * nodes go from stick to slip during the run, the gradient damage with
   * its bounds, the stress history; output in @p directory, a checkpoint
   * every @p every_steps steps; then the parameter file text @p extra.
   */
  inline void
  set_checkpoint_scene(ParameterHandler  &prm,
                       const std::string &directory,
                       const unsigned int every_steps,
                       const std::string &extra = "")
  {
    Simulator<2>::declare_parameters(prm);
    prm.parse_input(SOURCE_DIR "/../../prm/paper_fig1.prm");
    prm.parse_input_from_string(R"(
      subsection Geometry
        set Subdivisions = 8, 8
      end
      subsection Contact
        set Friction bound = 20
      end
      subsection Time
        set End time  = 0.4
        set Time step = 0.02
      end
      subsection Solver
        set Relative tolerance = 1e-12
      end
      subsection Output
        set Output every                = 5
        set Deterministic screen output = true
      end)");
    prm.enter_subsection("Output");
    prm.set("Directory", directory);
    prm.leave_subsection();
    prm.enter_subsection("Checkpoint");
    prm.set("Every steps", std::to_string(every_steps));
    prm.leave_subsection();
    if (!extra.empty())
      prm.parse_input_from_string(extra);
  }

  /**
   * A stream buffer that copies what is written into a file and raises
   * SIGTERM in this thread once a line starting with @p trigger is
   * complete: the signal arrives in the middle of the run, at a known step,
   * through the operating system as a kill would deliver it.
   */
  class SignalOnLine : public std::streambuf
  {
  public:
    SignalOnLine(const std::string &filename, const std::string &trigger)
      : file(filename)
      , trigger(trigger)
    {}

  protected:
    int
    overflow(const int c) override
    {
      if (c == traits_type::eof())
        return 0;
      file.put(static_cast<char>(c));
      if (c != '\n')
        line += static_cast<char>(c);
      else
        {
          if (!trigger.empty() && line.rfind(trigger, 0) == 0)
            {
              trigger.clear();
              std::raise(SIGTERM);
            }
          line.clear();
        }
      return c;
    }

  private:
    std::ofstream file;
    std::string   trigger;
    std::string   line;
  };

  /**
   * Run the scene of @p prm on @p communicator with its screen output in
   * @p log (SIGTERM after the line that starts with @p trigger, if not
   * empty). Returns whether the run stopped for a resume.
   */
  template <int dim = 2>
  bool
  run_logged(ParameterHandler  &prm,
             const MPI_Comm     communicator,
             const std::string &log,
             const std::string &trigger = "")
  {
    SignalOnLine    buffer(log, trigger);
    std::streambuf *old = std::cout.rdbuf(&buffer);
    try
      {
        Simulator<dim> simulator(prm, SOURCE_DIR "/../../prm", communicator);
        simulator.run();
        std::cout.rdbuf(old);
        return simulator.stopped_for_resume();
      }
    catch (...)
      {
        std::cout.rdbuf(old);
        throw;
      }
  }

  /// The lines of a text file.
  inline std::vector<std::string>
  read_lines(const std::string &filename)
  {
    std::ifstream            in(filename);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }

  /// The fields of a checkpoint of the scene, loaded on a communicator.
  struct CheckpointState
  {
    explicit CheckpointState(const MPI_Comm communicator)
      : triangulation(communicator)
      , fe(FE_Q<2>(1), 2, FE_Q<2>(1), 1)
      , dof_handler(triangulation)
    {}

    parallel::distributed::Triangulation<2> triangulation;
    FESystem<2>                             fe;
    DoFHandler<2>                           dof_handler;
    /// The solution, the last three increments and the active sets.
    std::vector<LA::MPI::Vector> vectors;
    StressHistory<2>             history;
  };

  /**
   * Read the fields of the checkpoint in @p folder, of the scene of
   * @p prm, as a resumed run does (CheckpointFields, 2 x 2 Gauss points).
   */
  inline void
  load_checkpoint_state(ParameterHandler  &prm,
                        const std::string &folder,
                        CheckpointState   &state)
  {
    Geometry<2> geometry;
    geometry.parse_parameters(prm,
                              SOURCE_DIR "/../../prm",
                              state.triangulation.get_communicator());
    geometry.create_coarse_mesh(state.triangulation);
    state.triangulation.load(folder + "/mesh");
    state.dof_handler.distribute_dofs(state.fe);
    state.vectors.resize(5);
    std::vector<LA::MPI::Vector *> pointers;
    for (auto &v : state.vectors)
      {
        v.reinit(state.dof_handler.locally_owned_dofs(),
                 state.triangulation.get_communicator());
        pointers.push_back(&v);
      }
    for (const auto &cell : state.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        state.history.initialize(cell, 4);
    CheckpointFields::load(state.triangulation,
                           state.dof_handler,
                           pointers,
                           state.history,
                           4);
  }
} // namespace VPContact

#endif
