// The metadata of a checkpoint as JSON, and its manifest of file sizes and
// checksums.
// Boost's property tree includes boost/bind.hpp, which warns about its global
// placeholders unless told that they are expected.
#define BOOST_BIND_GLOBAL_PLACEHOLDERS

#include <vpcontact/checkpoint/checkpoint_metadata.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <boost/crc.hpp>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unistd.h>
#include <vector>

namespace VPContact
{
  namespace
  {
    using boost::property_tree::ptree;

    // 17 significant digits: the double reads back to the same bits.
    std::string
    exact_text(const double value)
    {
      char buffer[32];
      std::snprintf(buffer, sizeof(buffer), "%.17g", value);
      return buffer;
    }

    // A subtree whose keys are taken literally: ptree's put() would split
    // "Section/Entry.with.dots" at the dots.
    template <typename Map>
    ptree
    literal_tree(const Map &map)
    {
      ptree tree;
      for (const auto &[key, value] : map)
        {
          std::string text;
          if constexpr (std::is_same_v<typename Map::mapped_type, double>)
            text = exact_text(value);
          else
            text = value;
          tree.push_back({key, ptree(text)});
        }
      return tree;
    }

    const ptree &
    child(const ptree &tree, const std::string &key)
    {
      const auto found = tree.find(key);
      if (found == tree.not_found())
        throw std::runtime_error("the entry '" + key + "' is missing");
      return found->second;
    }

    double
    to_double(const std::string &text)
    {
      std::size_t  end   = 0;
      const double value = std::stod(text, &end);
      if (end != text.size())
        throw std::runtime_error("'" + text + "' is not a number");
      return value;
    }

    unsigned long long
    to_count(const std::string &text)
    {
      std::size_t              end   = 0;
      const unsigned long long value = std::stoull(text, &end);
      if (end != text.size())
        throw std::runtime_error("'" + text + "' is not a whole number");
      return value;
    }

    // The size and CRC-32 of a file, read in blocks of 1 MiB.
    std::pair<unsigned long long, unsigned int>
    size_and_checksum(const std::string &filename)
    {
      std::ifstream in(filename, std::ios::binary);
      AssertThrow(in.good(),
                  dealii::ExcMessage("Cannot read the checkpoint file "
                                     + filename + "."));
      boost::crc_32_type crc;
      std::vector<char>  block(1 << 20);
      unsigned long long size = 0;
      while (in)
        {
          in.read(block.data(), block.size());
          crc.process_bytes(block.data(), in.gcount());
          size += in.gcount();
        }
      return {size, crc.checksum()};
    }

    // fsync: the data of a file (or the entries of a folder) reach the disk
    // before the rename that publishes them, so that a checkpoint survives
    // a crash of the node, not only of the program.
    void
    flush_to_disk(const std::string &path)
    {
      const int descriptor = ::open(path.c_str(), O_RDONLY);
      AssertThrow(descriptor >= 0,
                  dealii::ExcMessage("Cannot open " + path
                                     + " to flush it to disk."));
      const int status = ::fsync(descriptor);
      ::close(descriptor);
      AssertThrow(status == 0,
                  dealii::ExcMessage("Cannot flush " + path
                                     + " to disk (disk full or I/O error?)."));
    }

    // The names of the files the manifest of @p folder lists (none if it
    // has no manifest).
    std::set<std::string>
    listed_files(const std::string &folder)
    {
      std::set<std::string> names;
      std::ifstream         in(folder + "/" + CheckpointManifest::filename);
      for (std::string line; std::getline(in, line);)
        {
          std::istringstream words(line);
          std::string        size, checksum, name;
          if (!line.empty() && line[0] != '#'
              && (words >> size >> checksum >> name))
            names.insert(name);
        }
      return names;
    }

    // "a, b and c".
    std::string
    name_list(const std::vector<std::string> &names)
    {
      std::string text;
      for (unsigned int i = 0; i < names.size(); ++i)
        text += (i == 0                ? "" :
                 i + 1 == names.size() ? " and " :
                                         ", ")
                + names[i];
      return text;
    }

    // The files of the checkpoint in @p folder that its manifest certifies,
    // sorted (the manifest of a state is then the same). Throws if one
    // named in @p expected_sizes does not have the size meant to be
    // written, or if the folder holds a file the checkpoint did not write.
    std::vector<std::string>
    certified_files(const std::string                           &folder,
                    const std::map<std::string, std::uintmax_t> &expected_sizes)
    {
      // A write that ran out of disk space may have ended short without an
      // error on the way: a file that does not have the size it was meant
      // to have is not certified.
      for (const auto &[name, bytes] : expected_sizes)
        {
          std::error_code error;
          const auto      size
            = std::filesystem::file_size(folder + "/" + name, error);
          AssertThrow(!error && size == bytes,
                      dealii::ExcMessage(
                        "the checkpoint file " + folder + "/" + name + " has "
                        + (error ? std::string("not been written") :
                                   std::to_string(size) + " bytes")
                        + ", " + std::to_string(bytes)
                        + " were meant to be written (disk full?)."));
        }

      // The manifest lists the files the checkpoint wrote, and only those:
      // a file of the user's is never certified, and so never removed with
      // the checkpoint.
      std::vector<std::string> foreign;
      for (const auto &name : CheckpointManifest::foreign_files(folder))
        if (expected_sizes.count(name) == 0)
          foreign.push_back(name);
      AssertThrow(foreign.empty(),
                  dealii::ExcMessage(
                    folder + " holds " + name_list(foreign)
                    + ", which the checkpoint did not write. Move "
                    + (foreign.size() == 1 ? "it" : "them")
                    + " out of the checkpoint folder."));
      std::vector<std::string> names;
      for (const auto &entry : std::filesystem::directory_iterator(folder))
        {
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file() && name != CheckpointManifest::filename
              && name.find(".tmp") == std::string::npos
              && name.find(".locktest.") == std::string::npos
              && (CheckpointManifest::is_checkpoint_file(name)
                  || expected_sizes.count(name) > 0))
            names.push_back(name);
        }
      std::sort(names.begin(), names.end());
      return names;
    }
  } // namespace



  std::string
  CheckpointMetadata::to_json() const
  {
    ptree tree;
    tree.put("format version", format_version);
    tree.put("step", step);
    tree.put("time", exact_text(time));
    tree.put("cycle", cycle);
    tree.put("MPI ranks", n_ranks);
    tree.put("coarse cells", n_coarse_cells);
    tree.put("active cells", n_active_cells);
    tree.put("dofs", n_dofs);
    ptree outputs;
    for (const auto &[output_time, file] : field_outputs)
      {
        ptree entry;
        entry.put("time", exact_text(output_time));
        entry.put("file", file);
        outputs.push_back({"", entry});
      }
    tree.add_child("field outputs", outputs);
    tree.put("output directory", output_directory);
    tree.add_child("counters", literal_tree(counters));
    tree.add_child("parameters", literal_tree(parameters));
    tree.put("statistics", statistics_csv);
    std::ostringstream out;
    boost::property_tree::write_json(out, tree);
    return out.str();
  }



  CheckpointMetadata
  CheckpointMetadata::from_json(const std::string &text)
  {
    ptree tree;
    try
      {
        std::istringstream in(text);
        boost::property_tree::read_json(in, tree);
      }
    catch (const boost::property_tree::json_parser_error &e)
      {
        throw std::runtime_error("it is not valid JSON (" + e.message()
                                 + ", line " + std::to_string(e.line()) + ")");
      }

    CheckpointMetadata metadata;
    try
      {
        const auto version = to_count(child(tree, "format version").data());
        if (version != format_version)
          throw std::runtime_error(
            "its format version is " + std::to_string(version)
            + ", this program reads version " + std::to_string(format_version));
        metadata.step           = to_count(child(tree, "step").data());
        metadata.time           = to_double(child(tree, "time").data());
        metadata.cycle          = to_count(child(tree, "cycle").data());
        metadata.n_ranks        = to_count(child(tree, "MPI ranks").data());
        metadata.n_coarse_cells = to_count(child(tree, "coarse cells").data());
        metadata.n_active_cells = to_count(child(tree, "active cells").data());
        metadata.n_dofs         = to_count(child(tree, "dofs").data());
        for (const auto &[key, entry] : child(tree, "field outputs"))
          metadata.field_outputs.emplace_back(to_double(
                                                child(entry, "time").data()),
                                              child(entry, "file").data());
        // Absent in checkpoints of versions before it was recorded.
        metadata.output_directory
          = tree.get<std::string>("output directory", "");
        for (const auto &[key, entry] : child(tree, "counters"))
          metadata.counters[key] = to_double(entry.data());
        for (const auto &[key, entry] : child(tree, "parameters"))
          metadata.parameters[key] = entry.data();
        metadata.statistics_csv = child(tree, "statistics").data();
      }
    catch (const std::invalid_argument &)
      {
        throw std::runtime_error("an entry is not a number");
      }
    catch (const std::out_of_range &)
      {
        throw std::runtime_error("an entry is out of range");
      }
    return metadata;
  }



  namespace CheckpointManifest
  {
    void
    write(const std::string                           &folder,
          const std::map<std::string, std::uintmax_t> &expected_sizes)
    {
      const std::vector<std::string> names
        = certified_files(folder, expected_sizes);

      std::ostringstream manifest;
      manifest << "# vpcontact checkpoint manifest: size in bytes, CRC-32, "
                  "file\n";
      for (const auto &name : names)
        {
          const std::string path = folder + "/" + name;
          flush_to_disk(path);
          const auto [size, checksum] = size_and_checksum(path);
          char line[64];
          std::snprintf(line, sizeof(line), " %08x ", checksum);
          manifest << size << line << name << '\n';
        }

      // Through a temporary file and a rename, then flushed with the
      // folder: the manifest is either absent or complete.
      const std::string path      = folder + "/" + filename;
      const std::string temporary = path + ".tmp";
      {
        std::ofstream out(temporary);
        out << manifest.str();
        out.close();
        AssertThrow(out.good(),
                    dealii::ExcMessage("Cannot write the checkpoint manifest "
                                       + temporary
                                       + " (disk full or no permission?)."));
      }
      flush_to_disk(temporary);
      std::filesystem::rename(temporary, path);
      flush_to_disk(folder);
    }



    std::string
    check(const std::string &folder)
    {
      std::ifstream in(folder + "/" + filename);
      if (!in)
        return "it has no " + filename + " (the checkpoint was not completed)";
      std::string  line;
      unsigned int n_files = 0;
      while (std::getline(in, line))
        {
          if (line.empty() || line[0] == '#')
            continue;
          std::istringstream words(line);
          unsigned long long size = 0;
          std::string        checksum_text, name;
          if (!(words >> size >> checksum_text >> name))
            return "its " + filename + " is damaged (a line does not read "
                   + "'size checksum file')";
          ++n_files;
          const std::string path = folder + "/" + name;
          if (!std::filesystem::is_regular_file(path))
            return "the file " + name + " is missing";
          const auto [actual_size, checksum] = size_and_checksum(path);
          if (actual_size != size)
            return "the file " + name + " has " + std::to_string(actual_size)
                   + " bytes, the manifest records " + std::to_string(size)
                   + (actual_size < size ? " (truncated)" : "");
          char actual_text[16];
          std::snprintf(actual_text, sizeof(actual_text), "%08x", checksum);
          if (checksum_text != actual_text)
            return "the file " + name
                   + " has changed since it was written (its CRC-32 is "
                   + actual_text + ", the manifest records " + checksum_text
                   + ")";
        }
      if (n_files == 0)
        return "its " + filename + " lists no files";
      return "";
    }



    bool
    is_lock_test_file(const std::string &name, const std::string &file)
    {
      // Open MPI's MPI-IO tests file locking on a file it writes through a
      // file <file>.locktest.<rank> beside it, which it removes again; a
      // run killed meanwhile leaves it.
      const std::string prefix = file + ".locktest.";
      return name.size() > prefix.size()
             && name.compare(0, prefix.size(), prefix) == 0
             && std::all_of(name.begin() + prefix.size(),
                            name.end(),
                            [](const char c) { return std::isdigit(c); });
    }



    bool
    is_checkpoint_file(const std::string &name)
    {
      for (const std::string &own : {std::string("mesh"),
                                     std::string("mesh.info"),
                                     std::string("mesh_fixed.data"),
                                     std::string("mesh_variable.data"),
                                     std::string("checkpoint.json"),
                                     filename,
                                     marker})
        if (name == own || name == own + ".tmp" || is_lock_test_file(name, own))
          return true;
      return false;
    }



    std::vector<std::string>
    foreign_files(const std::string &folder)
    {
      std::vector<std::string> names;
      std::error_code          error;
      if (!std::filesystem::is_directory(folder, error))
        return names;
      const std::set<std::string> listed = listed_files(folder);
      for (const auto &entry :
           std::filesystem::directory_iterator(folder, error))
        {
          const std::string name = entry.path().filename().string();
          if (!is_checkpoint_file(name) && listed.count(name) == 0)
            names.push_back(name);
        }
      std::sort(names.begin(), names.end());
      return names;
    }



    void
    remove(const std::string &folder)
    {
      std::error_code error;
      if (!std::filesystem::exists(folder, error))
        return;
      // The manifest goes last: until then the folder says what it holds.
      std::set<std::string> names = listed_files(folder);
      for (const auto &entry :
           std::filesystem::directory_iterator(folder, error))
        if (is_checkpoint_file(entry.path().filename().string()))
          names.insert(entry.path().filename().string());
      names.erase(filename);
      for (const auto &name : names)
        std::filesystem::remove(folder + "/" + name, error);
      std::filesystem::remove(folder + "/" + filename, error);
      // remove() takes a folder only when it is empty.
      std::filesystem::remove(folder, error);
      const std::vector<std::string> left = foreign_files(folder);
      AssertThrow(!std::filesystem::exists(folder),
                  dealii::ExcMessage(
                    "cannot remove the checkpoint folder " + folder
                    + (left.empty() ?
                         " (" + error.message() + ")" :
                         ": it holds " + name_list(left)
                           + ", which vpcontact did not write and leaves "
                             "as it is")));
    }
  } // namespace CheckpointManifest
} // namespace VPContact
