// The field outputs of a resumed run: those its checkpoint lists, brought
// into the output folder of the run, so that its .pvd record lists only
// files that are there.
#include <vpcontact/postprocess/resumed_field_outputs.h>

#include <deal.II/base/exceptions.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace VPContact
{
  namespace
  {
    // The files of the field output @p pvtu in @p folder: the record and
    // the pieces it names (as many as the ranks of the run that wrote it).
    // Empty if the record is not there.
    std::vector<std::string>
    files_of_output(const std::string &folder, const std::string &pvtu)
    {
      std::ifstream in(folder + "/" + pvtu);
      if (!in)
        return {};
      const std::string        text((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
      std::vector<std::string> files{pvtu};
      const std::string        key = "Source=\"";
      auto                     at  = text.find(key);
      while (at != std::string::npos)
        {
          const auto start = at + key.size();
          const auto end   = text.find('"', start);
          files.push_back(text.substr(start, end - start));
          at = text.find(key, end);
        }
      return files;
    }

    // Put a file of @p source's at @p target: a hard link (no disk space,
    // and safe, since this program replaces its files by a rename and never
    // changes one in place), else a copy; through a temporary name, so that
    // @p target is whole or absent. Returns whether it copied.
    bool
    place_file(const std::string &source, const std::string &target)
    {
      const std::string temporary = target + ".tmp";
      std::error_code   error;
      std::filesystem::remove(temporary, error);
      std::filesystem::create_hard_link(source, temporary, error);
      const bool copied = static_cast<bool>(error);
      if (copied && !std::filesystem::copy_file(source, temporary, error))
        {
          std::filesystem::remove(temporary);
          AssertThrow(false,
                      dealii::ExcMessage("cannot copy " + source + " to "
                                         + target + " (" + error.message()
                                         + ")"));
        }
      std::filesystem::rename(temporary, target);
      return copied;
    }

  } // namespace



  std::pair<FieldOutputRecord, std::string>
  bring_field_outputs(const FieldOutputRecord &outputs,
                      const std::string       &from,
                      const std::string       &to)
  {
    std::error_code error;
    const bool      elsewhere
      = !from.empty() && !std::filesystem::equivalent(from, to, error);
    FieldOutputRecord        kept;
    std::vector<std::string> missing;
    unsigned int             n_files = 0, n_copies = 0;
    for (const auto &[time, pvtu] : outputs)
      {
        const std::string              source   = elsewhere ? from : to;
        const std::vector<std::string> files    = files_of_output(source, pvtu);
        bool                           complete = !files.empty();
        for (const auto &file : files)
          complete
            = complete
              && std::filesystem::is_regular_file(source + "/" + file, error);
        if (!complete)
          {
            missing.push_back(pvtu);
            continue;
          }
        if (elsewhere)
          for (const auto &file : files)
            {
              n_copies += place_file(from + "/" + file, to + "/" + file);
              ++n_files;
            }
        kept.emplace_back(time, pvtu);
      }
    std::string note;
    if (n_files > 0)
      note += "Field outputs: the " + std::to_string(kept.size())
              + " of the checkpointed run (" + std::to_string(n_files)
              + " files) brought from " + from + " into " + to + " ("
              + (n_copies == 0 ? "hard links" :
                                 std::to_string(n_copies) + " copies")
              + "), so that solution.pvd lists files of this folder.\n";
    if (!missing.empty())
      note += "Field outputs: " + missing[0]
              + (missing.size() > 1 ?
                   " and " + std::to_string(missing.size() - 1) + " more" :
                   std::string())
              + " of the checkpointed run are missing or incomplete in "
              + (elsewhere ? from : to) + "; solution.pvd leaves them out.\n";
    return {kept, note};
  }
} // namespace VPContact
