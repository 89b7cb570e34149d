// Checks the files and folders a run is given before anything computes:
// - parameter files: a folder or a missing file as the scene, a file that
//   includes itself, two that include each other, an include of a folder
//   are refused with a message naming the file; nested relative includes
//   are read from the including file's folder, and a parse error names the
//   file and line it came from;
// - Output/Directory holding files of the names a run writes, not written by
//   vpcontact: refused, and those files left unchanged; other files of the
//   user's in it are kept;
// - Checkpoint/Folder: an existing folder of the user's as FOLDER, FOLDER.old
//   or FOLDER.new, the output folder itself and the working directory are
//   refused before the run, and the user's files are left unchanged; the
//   program's own folders rotate as before.
#include <vpcontact/checkpoint/checkpointing.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parameter_file.h>
#include <vpcontact/postprocess/output_writer.h>

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>

using namespace VPContact;
namespace fs = std::filesystem;

namespace
{
  void
  write(const std::string &path, const std::string &text)
  {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path) << text;
  }

  std::string
  read(const std::string &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  // The message of what @p task threw, with the test's folder left out.
  template <typename Task>
  void
  expect_refusal(const std::string &what, const Task &task)
  {
    try
      {
        task();
        std::cout << what << ": accepted" << std::endl;
      }
    catch (const std::exception &e)
      {
        const std::string here = fs::current_path().string() + "/";
        std::cout << what << ": refused: "
                  << std::regex_replace(error_message(e), std::regex(here), "")
                  << std::endl;
      }
  }

  void
  check_parameter_files()
  {
    write("prm/a/top.prm",
          "subsection A\n  include ../shared.prm\nend\nset X = 1\n");
    write("prm/shared.prm", "# shared\nset Y = 2\n");
    const ParameterFile file = read_parameter_file("prm/a/top.prm");
    std::cout << "nested relative include:\n" << file.text;
    std::cout << "line 3 of the text comes from " << file.origins[2].first
              << ":" << file.origins[2].second << std::endl;
    std::cout << file.locate("Line <3> of file <prm/a/top.prm>: bad")
              << std::endl;

    expect_refusal("a folder as the scene", [] { read_parameter_file("prm"); });
    expect_refusal("a missing scene",
                   [] { read_parameter_file("prm/none.prm"); });
    write("prm/self.prm", "set X = 1\ninclude self.prm\n");
    expect_refusal("a file that includes itself",
                   [] { read_parameter_file("prm/self.prm"); });
    write("prm/ping.prm", "include pong.prm\n");
    write("prm/pong.prm", "include ping.prm\n");
    expect_refusal("two files that include each other",
                   [] { read_parameter_file("prm/ping.prm"); });
    write("prm/folder.prm", "include a\n");
    expect_refusal("an include of a folder",
                   [] { read_parameter_file("prm/folder.prm"); });
  }

  // Output/Directory @p output and Checkpoint/Folder @p folder as a scene
  // would set them.
  void
  declare(ParameterHandler  &prm,
          const std::string &output,
          const std::string &folder)
  {
    OutputWriter<2>::declare_parameters(prm);
    Checkpointing::declare_parameters(prm);
    prm.enter_subsection("Output");
    prm.set("Directory", output);
    prm.leave_subsection();
    prm.enter_subsection("Checkpoint");
    prm.set("Every steps", "1");
    prm.set("Folder", folder);
    prm.leave_subsection();
  }

  void
  check_output_folder(const MPI_Comm communicator)
  {
    write("user_results/statistics.csv", "the user's table\n");
    write("user_notes/notes.txt", "the user's notes\n");
    for (const std::string folder : {"user_results", "user_notes"})
      {
        ParameterHandler prm;
        declare(prm, folder, "");
        OutputWriter<2> writer;
        writer.parse_parameters(prm);
        expect_refusal("Output/Directory = " + folder,
                       [&] { writer.prepare_directory(communicator); });
      }
    std::cout << "user_results/statistics.csv: "
              << read("user_results/statistics.csv")
              << "user_notes/notes.txt: " << read("user_notes/notes.txt");
  }

  void
  check_checkpoint_folders(const MPI_Comm communicator)
  {
    write("thesis/thesis.tex", "\\chapter{Results}\n");
    write("plain/run.old/thesis.tex", "\\chapter{Old}\n");
    write("pending/run.new/draft.tex", "\\chapter{Draft}\n");
    // A run killed between making FOLDER.new and writing its marker leaves
    // the folder empty. It holds nothing to lose, so it is accepted.
    fs::create_directories("empty/run.new");
    const std::vector<std::pair<std::string, std::string>> cases
      = {{"results", "thesis"},
         {"results", "plain/run"},
         {"results", "pending/run"},
         {"results", "empty/run"},
         {"results", "results"},
         {"results/deep", "results"},
         {"results", "."}};
    for (const auto &[output, folder] : cases)
      {
        ParameterHandler prm;
        declare(prm, output, folder);
        Checkpointing checkpointing;
        checkpointing.parse_parameters(prm, output);
        expect_refusal("Output/Directory = " + output
                         + ", Checkpoint/Folder = " + folder,
                       [&] {
                         checkpointing.check_folders(output, communicator);
                       });
      }
    std::cout << "thesis/thesis.tex: " << read("thesis/thesis.tex")
              << "plain/run.old/thesis.tex: "
              << read("plain/run.old/thesis.tex")
              << "pending/run.new/draft.tex: "
              << read("pending/run.new/draft.tex");

    // The program's own folders: two checkpoints rotate into FOLDER and
    // FOLDER.old, both marked.
    ParameterHandler prm;
    declare(prm, "results", "own/checkpoint");
    Checkpointing checkpointing;
    checkpointing.parse_parameters(prm, "results");
    checkpointing.check_folders("results", communicator);
    for (unsigned int n = 1; n <= 2; ++n)
      {
        const std::string folder
          = checkpointing.start_writing(1e3, communicator);
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          write(folder + "/data", "step " + std::to_string(n) + "\n");
        CheckpointMetadata metadata;
        metadata.step = n;
        checkpointing.finish_writing(metadata, {{"data", 7}}, communicator);
      }
    std::cout << "own/checkpoint/data: " << read("own/checkpoint/data")
              << "own/checkpoint.old/data: " << read("own/checkpoint.old/data")
              << "own/checkpoint.new exists: "
              << fs::exists("own/checkpoint.new") << std::endl;

    // A file that does not have the size it was meant to have is not
    // certified, and the previous checkpoint stays.
    const std::string folder = checkpointing.start_writing(1e3, communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      write(folder + "/data", "step\n");
    expect_refusal("a short checkpoint file", [&] {
      checkpointing.finish_writing(CheckpointMetadata(),
                                   {{"data", 7}},
                                   communicator);
    });
    std::cout << "own/checkpoint/data: " << read("own/checkpoint/data");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string folder : {"prm",
                                   "user_results",
                                   "user_notes",
                                   "thesis",
                                   "plain",
                                   "pending",
                                   "empty",
                                   "results",
                                   "own"})
    fs::remove_all(folder);
  check_parameter_files();
  check_output_folder(MPI_COMM_WORLD);
  check_checkpoint_folders(MPI_COMM_WORLD);
}
