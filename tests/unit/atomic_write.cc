// Unit test: write_file_atomically() with a writer function. A write that
// completes replaces the file; one whose writer throws leaves the previous
// file as it was, removes its temporary file and passes the exception on.
#include <vpcontact/postprocess/output_writer.h>

#include <deal.II/base/exceptions.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace
{
  std::string
  content_of(const std::string &filename)
  {
    std::ifstream      in(filename);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void
  report(const std::string &what, const std::string &filename)
  {
    std::cout << what << ": '" << content_of(filename) << "', temporary file "
              << (std::filesystem::exists(filename + ".tmp") ? "left" : "gone")
              << std::endl;
  }
} // namespace

int
main()
{
  dealii::deal_II_exceptions::disable_abort_on_exception();
  const std::string folder = "atomic_write_files";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directory(folder);
  const std::string file = folder + "/piece.vtu";

  VPContact::write_file_atomically(file, "old");
  VPContact::write_file_atomically(file, [](std::ostream &out) {
    out << "new ";
    out << "content";
  });
  report("complete write", file);

  try
    {
      VPContact::write_file_atomically(file, [](std::ostream &out) {
        out << "half of a piece";
        throw std::runtime_error("the writer failed");
      });
      std::cout << "no exception" << std::endl;
    }
  catch (const std::runtime_error &e)
    {
      std::cout << "passed on: " << e.what() << std::endl;
    }
  report("after a failed writer", file);

  std::filesystem::remove_all(folder);
}
