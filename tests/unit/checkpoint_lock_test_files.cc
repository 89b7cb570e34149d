// Checks that the lock-test files MPI-IO leaves beside a checkpoint's data
// when a run is killed while it saves (mesh_fixed.data.locktest.0) belong to
// the checkpoint: a resumed run neither calls them the user's nor stops at
// them, and the rotation removes them with the folder; a file of another
// name stays the user's.
#include <vpcontact/checkpoint/checkpoint_metadata.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

using namespace VPContact;

namespace
{
  void
  touch(const std::string &path)
  {
    std::ofstream(path) << "x";
  }

  void
  print_foreign(const std::string &folder)
  {
    std::cout << "foreign files in " << folder << ":";
    for (const auto &name : CheckpointManifest::foreign_files(folder))
      std::cout << ' ' << name;
    std::cout << '\n';
  }
} // namespace

int
main()
{
  for (const std::string name : {"mesh_fixed.data.locktest.0",
                                 "mesh_variable.data.locktest.12",
                                 "mesh_fixed.data.locktest.",
                                 "mesh_fixed.data.locktest.x",
                                 "notes.locktest.0"})
    std::cout << name << ": "
              << (CheckpointManifest::is_checkpoint_file(name) ?
                    "checkpoint file" :
                    "not a checkpoint file")
              << '\n';

  // A checkpoint folder that a killed save left: its marker, a lock test
  // file, and nothing else of the user's; removed whole.
  const std::string folder = "checkpoint.new";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directory(folder);
  touch(folder + "/" + CheckpointManifest::marker);
  touch(folder + "/mesh_fixed.data.locktest.0");
  print_foreign(folder);
  CheckpointManifest::remove(folder);
  std::cout << folder
            << " removed: " << (std::filesystem::exists(folder) ? "no" : "yes")
            << '\n';

  // The same with a file of the user's: it stays, and so does the folder.
  std::filesystem::create_directory(folder);
  touch(folder + "/" + CheckpointManifest::marker);
  touch(folder + "/mesh_fixed.data.locktest.0");
  touch(folder + "/notes.txt");
  print_foreign(folder);
  try
    {
      CheckpointManifest::remove(folder);
    }
  catch (const std::exception &)
    {
      std::cout << "remove() refused" << '\n';
    }
  std::cout << "notes.txt kept: "
            << (std::filesystem::exists(folder + "/notes.txt") ? "yes" : "no")
            << '\n';
  std::filesystem::remove_all(folder);
}
