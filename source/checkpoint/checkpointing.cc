// Section "Checkpoint": the schedule of checkpoints, stopping on a signal, and
// putting a checkpoint in place and finding it again.
#include <vpcontact/checkpoint/checkpointing.h>
#include <vpcontact/input/input_error.h>
#include <vpcontact/input/parameter_listing.h>
#include <vpcontact/postprocess/output_writer.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <limits.h>
#include <set>
#include <sstream>
#include <unistd.h>

namespace VPContact
{
  namespace
  {
    // Whether @p folder is absent or a checkpoint folder of this program:
    // it carries the marker, or (written before markers existed) a manifest
    // of this program's format.
    bool
    absent_or_own(const std::string &folder)
    {
      std::error_code error;
      if (!std::filesystem::exists(folder, error))
        return true;
      if (!std::filesystem::is_directory(folder, error))
        return false;
      // A run killed between making a checkpoint folder and writing its
      // marker leaves it empty; an empty folder holds nothing to lose, so
      // the rotation may replace it and a resumed run is not stopped by it.
      if (std::filesystem::is_empty(folder, error) && !error)
        return true;
      if (has_folder_marker(folder, CheckpointManifest::marker))
        return true;
      std::ifstream in(folder + "/" + CheckpointManifest::filename);
      std::string   first_line;
      std::getline(in, first_line);
      return first_line.rfind("# vpcontact checkpoint manifest", 0) == 0;
    }

    // Whether @p inner is @p outer or lies inside it (both made absolute).
    bool
    is_within(const std::filesystem::path &inner,
              const std::filesystem::path &outer)
    {
      const auto a
        = std::filesystem::weakly_canonical(std::filesystem::absolute(inner));
      const auto b
        = std::filesystem::weakly_canonical(std::filesystem::absolute(outer));
      const auto mismatch
        = std::mismatch(b.begin(), b.end(), a.begin(), a.end());
      return mismatch.first == b.end();
    }

    // Parameters that may change between a run and its resumption: where
    // and how the output goes, the linear solver (a tolerance changes the
    // result only at the level of that tolerance), and the end time (a
    // finished run may be continued further).
    bool
    may_change_on_resume(const std::string &entry)
    {
      for (const std::string section : {"Output/", "Checkpoint/", "Solver/"})
        if (entry.rfind(section, 0) == 0)
          return true;
      return entry == "Time/End time";
    }

    // Read the checkpoint in @p folder into @p metadata, once its manifest
    // has been checked. Returns what makes it unusable, or "".
    std::string
    read_candidate(const std::string &folder, CheckpointMetadata &metadata)
    {
      std::string problem = CheckpointManifest::check(folder);
      if (problem.empty())
        try
          {
            std::ifstream      in(folder + "/checkpoint.json");
            std::ostringstream text;
            text << in.rdbuf();
            metadata = CheckpointMetadata::from_json(text.str());
          }
        catch (const std::exception &e)
          {
            problem
              = "its checkpoint.json cannot be read: " + std::string(e.what());
          }
      return problem;
    }

    // The index of the usable one among the existing @p candidates with the
    // latest step (the first of equals), its metadata in @p newest, or -1;
    // why each unusable one is unusable goes to @p problems.
    int
    newest_usable(const std::vector<std::string>     &candidates,
                  std::map<std::string, std::string> &problems,
                  CheckpointMetadata                 &newest)
    {
      int chosen = -1;
      for (unsigned int i = 0; i < candidates.size(); ++i)
        {
          if (!std::filesystem::is_directory(candidates[i]))
            continue;
          CheckpointMetadata metadata;
          const std::string  problem = read_candidate(candidates[i], metadata);
          if (!problem.empty())
            problems[candidates[i]] = problem;
          else if (chosen < 0 || metadata.step > newest.step)
            {
              chosen = i;
              newest = metadata;
            }
        }
      return chosen;
    }

    // Rank 0's verdict on the @p candidates, the first of which is
    // @p folder itself, as find_checkpoint() hands it to every rank: the
    // error that stops the run, the notes for the screen, the folder to
    // read and its metadata as JSON.
    std::vector<std::string>
    checkpoint_verdict(const std::string                        &folder,
                       const std::vector<std::string>           &candidates,
                       const std::map<std::string, std::string> &problems,
                       const int                                 chosen,
                       const CheckpointMetadata                 &newest)
    {
      std::vector<std::string> verdict(4);
      if (chosen < 0 && problems.empty())
        verdict[0] = parameter_message(
          "Checkpoint/Resume from checkpoint",
          "true",
          "there is no checkpoint in " + folder
            + " (nor .new or .old next to it). Check Output/Directory and "
              "Checkpoint/Folder, or start the run without resuming.");
      else if (chosen < 0)
        {
          verdict[0] = parameter_message("Checkpoint/Resume from checkpoint",
                                         "true",
                                         "no complete checkpoint is left in "
                                           + folder + ":");
          for (const auto &[candidate, problem] : problems)
            verdict[0] += "\n  " + candidate + ": " + problem;
          verdict[0] += "\nStart the run afresh without resuming.";
        }
      else
        {
          for (const auto &[candidate, problem] : problems)
            verdict[1] += "Checkpoint: " + candidate
                          + " is not usable: " + problem + ".\n";
          if (chosen != 0)
            verdict[1] += "Checkpoint: resuming from " + candidates[chosen]
                          + " (step " + std::to_string(newest.step)
                          + ") instead of " + folder + ".\n";
          verdict[2] = candidates[chosen];
          verdict[3] = newest.to_json();
        }
      return verdict;
    }
  } // namespace



  void
  Checkpointing::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    {
      prm.declare_entry("Every steps",
                        "0",
                        Patterns::Integer(0),
                        "Write a checkpoint after every this many time steps "
                        "(the last step included, so that a finished run can "
                        "be continued to a later end time); 0: never.");
      prm.declare_entry("Every seconds",
                        "0",
                        Patterns::Double(0),
                        "Write a checkpoint at the end of the first step that "
                        "ends this many seconds of wall-clock time (measured "
                        "on rank 0) after the start of the run or the last "
                        "checkpoint, e.g. 3600 for one every hour; 0: never.");
      prm.declare_entry("Stop on signal",
                        "true",
                        Patterns::Bool(),
                        "On SIGINT (Ctrl-C), SIGTERM (kill, queue systems), "
                        "SIGUSR1 (which Open MPI's mpirun forwards to the "
                        "ranks) or SIGPIPE (the screen output piped into a "
                        "program that has ended, e.g. head), finish the "
                        "current step, write a checkpoint and stop with exit "
                        "status 75; a second SIGINT, SIGTERM or SIGUSR1 stops "
                        "at once. false: the signals act as usual.");
      prm.declare_entry("Resume from checkpoint",
                        "false",
                        Patterns::Bool(),
                        "Continue from the newest complete checkpoint in "
                        "Folder instead of starting at t = 0 (the command "
                        "line flag --resume sets this). The parameters of the "
                        "problem must be those of the checkpointed run; the "
                        "sections Output, Checkpoint and Solver and "
                        "Time/End time may differ.");
      prm.declare_entry("Folder",
                        "",
                        Patterns::Anything(),
                        "Folder of the checkpoint; empty: 'checkpoint' inside "
                        "Output/Directory. Next to it, FOLDER.new holds a "
                        "checkpoint while it is written and FOLDER.old the "
                        "previous one (the fallback if FOLDER is damaged). A "
                        "relative path is relative to the working directory.");
    }
    prm.leave_subsection();
  }



  void
  Checkpointing::parse_parameters(ParameterHandler  &prm,
                                  const std::string &directory)
  {
    output_directory = directory;
    prm.enter_subsection("Checkpoint");
    every_steps       = prm.get_integer("Every steps");
    every_seconds     = prm.get_double("Every seconds");
    catch_signals     = prm.get_bool("Stop on signal");
    resume_run        = prm.get_bool("Resume from checkpoint");
    checkpoint_folder = prm.get("Folder");
    prm.leave_subsection();
    folder_set_by_user = !checkpoint_folder.empty();
    if (checkpoint_folder.empty())
      checkpoint_folder = output_directory + "/checkpoint";
    // "ck/." and "a/.." name the folders "ck" and "." (whose .new would
    // otherwise be "ck/..new", inside it).
    checkpoint_folder
      = std::filesystem::path(checkpoint_folder).lexically_normal().string();
    while (checkpoint_folder.size() > 1 && checkpoint_folder.back() == '/')
      checkpoint_folder.pop_back();
    if (folder_set_by_user)
      check_path_length("Checkpoint/Folder", checkpoint_folder);

    parameters.clear();
    for (const auto &[entry, value] : parameter_values(prm))
      if (!may_change_on_resume(entry))
        parameters[entry] = value;
  }



  void
  Checkpointing::record_problem_input(const std::string &entry,
                                      const std::string &value)
  {
    parameters[entry] = value;
  }



  bool
  Checkpointing::resume() const
  {
    return resume_run;
  }



  bool
  Checkpointing::writes_periodically() const
  {
    return every_steps > 0 || every_seconds > 0;
  }



  bool
  Checkpointing::stops_on_signal() const
  {
    return catch_signals;
  }



  const std::string &
  Checkpointing::folder() const
  {
    return checkpoint_folder;
  }



  const std::map<std::string, std::string> &
  Checkpointing::problem_parameters() const
  {
    return parameters;
  }



  Checkpointing::Decision
  Checkpointing::decide(const unsigned int n,
                        const unsigned int n_steps,
                        const MPI_Comm     communicator)
  {
    // One reduction per step: the signal seen by any rank, and rank 0's
    // clock (the ranks' clocks need not agree, their decision must).
    const bool rank_zero = Utilities::MPI::this_mpi_process(communicator) == 0;
    const double elapsed = std::chrono::duration<double>(
                             std::chrono::steady_clock::now() - last_checkpoint)
                             .count();
    const int time_due
      = (rank_zero && every_seconds > 0 && elapsed >= every_seconds) ? 1 : 0;
    const int local[2]  = {StopSignalCatcher::caught_signal(), time_due};
    int       global[2] = {0, 0};
    const int ierr
      = MPI_Allreduce(local, global, 2, MPI_INT, MPI_MAX, communicator);
    AssertThrowMPI(ierr);

    Decision decision;
    decision.signal = global[0];
    decision.stop   = (decision.signal != 0 && n < n_steps);
    // With Every steps the last step is written too, so that a finished
    // run can be continued to a later end time.
    decision.write
      = decision.stop || global[1] == 1
        || (every_steps > 0 && (n % every_steps == 0 || n == n_steps));
    return decision;
  }



  std::string
  Checkpointing::ownership_problem() const
  {
    const std::string remedy
      = folder_set_by_user ?
          "Choose another Checkpoint/Folder" :
          "Choose another Output/Directory, or set Checkpoint/Folder";
    for (const std::string suffix : {"", ".new", ".old"})
      {
        const std::string folder = checkpoint_folder + suffix;
        if (!absent_or_own(folder))
          return folder
                 + " exists and is not a checkpoint folder of vpcontact (it "
                   "has no "
                 + CheckpointManifest::marker
                 + " file). The program replaces and removes only folders "
                   "it made. "
                 + remedy + ", or move that one away.";
        // The rotation removes and renames the folder: a file in it that
        // no checkpoint wrote would go with it.
        const std::vector<std::string> foreign
          = CheckpointManifest::foreign_files(folder);
        if (!foreign.empty())
          return folder + " holds " + foreign[0]
                 + (foreign.size() > 1 ?
                      " (and " + std::to_string(foreign.size() - 1) + " more)" :
                      std::string())
                 + ", which vpcontact did not write: a checkpoint folder "
                   "holds only the files of its checkpoint, and the "
                   "checkpoint rotation removes it. Move "
                 + foreign[0] + " out of " + folder + ". " + remedy
                 + " if that folder is not for checkpoints.";
      }
    return "";
  }



  std::string
  Checkpointing::folder_entry() const
  {
    // The entry the user set: Checkpoint/Folder, or Output/Directory, of
    // which the default checkpoint folder is a part.
    if (folder_set_by_user)
      return parameter_message("Checkpoint/Folder", checkpoint_folder, "");
    return "Output/Directory = " + output_directory + " (its checkpoints go to "
           + checkpoint_folder + "): ";
  }



  void
  Checkpointing::check_folders(const std::string &output_directory,
                               const MPI_Comm     communicator)
  {
    if (!writes_periodically() && !stops_on_signal())
      return;
    const std::string problem = problem_on_rank_zero(communicator, [&]() {
      // The rotation renames FOLDER: that must not be a folder the run
      // works in or writes its output into.
      const std::filesystem::path folder(checkpoint_folder);
      for (const auto &[name, path] :
           {std::pair<std::string, std::filesystem::path>{
              "the working directory",
              std::filesystem::current_path()},
            {"Output/Directory = " + output_directory, output_directory}})
        AssertThrow(!is_within(path, folder),
                    ExcMessage("the checkpoint rotation renames this folder, "
                               "and "
                               + name
                               + " lies in it. Give a folder of its own, "
                                 "e.g. the default (empty: 'checkpoint' "
                                 "inside Output/Directory)."));
      const std::string ownership = ownership_problem();
      AssertThrow(ownership.empty(), ExcMessage(ownership));
      // FOLDER.new and FOLDER.old must be names the file system takes.
      AssertThrow(folder.filename().string().size() + 4 <= NAME_MAX,
                  ExcMessage("the name is too long for the file system with "
                             "'.new' and '.old' appended (at most "
                             + std::to_string(NAME_MAX - 4)
                             + " characters). Give a shorter one."));
      // The folder next to which the checkpoints go must be writable now,
      // not only when the first checkpoint is due.
      const std::filesystem::path parent
        = folder.has_parent_path() ? folder.parent_path() : ".";
      std::error_code error;
      std::filesystem::create_directories(parent, error);
      AssertThrow(!error,
                  ExcMessage("cannot create the folder " + parent.string()
                             + " (" + error.message() + ")."));
      // A file of a name no one else uses, made and removed again: the
      // only test that also holds for root and for read-only mounts.
      const std::string probe
        = (parent / (".vpcontact-write-test-" + std::to_string(getpid())))
            .string();
      const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
      AssertThrow(fd >= 0,
                  ExcMessage("cannot write into the folder " + parent.string()
                             + "."));
      close(fd);
      std::filesystem::remove(probe);
      // The output folder's lock does not cover a Checkpoint/Folder
      // elsewhere, which another run may name too.
      folder_lock = std::make_unique<FolderLock>(checkpoint_folder + ".lock",
                                                 "its checkpoint folder "
                                                   + checkpoint_folder);
    });
    AssertThrow(problem.empty(), ExcMessage(folder_entry() + problem));
  }



  std::string
  Checkpointing::start_writing(const double   n_bytes,
                               const MPI_Comm communicator) const
  {
    const std::string new_folder = checkpoint_folder + ".new";
    const std::string problem    = problem_on_rank_zero(communicator, [&]() {
      const std::string ownership = ownership_problem();
      AssertThrow(ownership.empty(), ExcMessage(ownership));
      // A leftover of a run that stopped while writing is incomplete; its
      // files, and only those, go.
      CheckpointManifest::remove(new_folder);
      std::filesystem::create_directories(new_folder);
      write_folder_marker(new_folder, CheckpointManifest::marker);
      // p4est ends the program without a message when a write fails: a
      // checkpoint is written only where it fits, with room to spare.
      const auto space = std::filesystem::space(new_folder);
      AssertThrow(static_cast<double>(space.available) >= 1.5 * n_bytes,
                  ExcMessage("only " + to_text(space.available)
                             + " bytes are free on the disk of " + new_folder
                             + ", and this checkpoint needs about "
                             + to_text(std::round(n_bytes))
                             + ". Free space on that disk or give a "
                                  "Checkpoint/Folder on another one."));
    });
    AssertThrow(problem.empty(),
                ExcMessage("Writing the checkpoint failed: " + problem
                           + " The previous checkpoint, if any, is intact; "
                             "the run stops here."));
    return new_folder;
  }



  void
  Checkpointing::finish_writing(
    const CheckpointMetadata                    &metadata,
    const std::map<std::string, std::uintmax_t> &expected_sizes,
    const MPI_Comm                               communicator)
  {
    const std::string new_folder = checkpoint_folder + ".new";
    const std::string old_folder = checkpoint_folder + ".old";
    const std::string problem    = problem_on_rank_zero(communicator, [&]() {
      write_file_atomically(new_folder + "/checkpoint.json",
                            metadata.to_json());
      CheckpointManifest::write(new_folder, expected_sizes);
      // The manifest is on disk: the new checkpoint is complete. Only now
      // may the one before the previous go, if it is still this program's.
      const std::string ownership = ownership_problem();
      AssertThrow(ownership.empty(), ExcMessage(ownership));
      CheckpointManifest::remove(old_folder);
      if (std::filesystem::exists(checkpoint_folder))
        std::filesystem::rename(checkpoint_folder, old_folder);
      std::filesystem::rename(new_folder, checkpoint_folder);
    });
    AssertThrow(problem.empty(),
                ExcMessage("Writing the checkpoint " + checkpoint_folder
                           + " failed: " + problem
                           + " The previous checkpoint, if any, is intact."));
    last_checkpoint = std::chrono::steady_clock::now();
  }



  CheckpointMetadata
  Checkpointing::find_checkpoint(const MPI_Comm      communicator,
                                 ConditionalOStream &out) const
  {
    // Rank 0 examines the candidates, newest name first, and tells the
    // others which one to read (or why none). Nothing is handed to p4est
    // before its manifest has been checked.
    const std::vector<std::string> candidates = {checkpoint_folder,
                                                 checkpoint_folder + ".new",
                                                 checkpoint_folder + ".old"};
    std::vector<std::string>       verdict(4); // error, notes, folder, metadata
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::map<std::string, std::string> problems;
        CheckpointMetadata                 newest;
        const int chosen = newest_usable(candidates, problems, newest);
        verdict          = checkpoint_verdict(checkpoint_folder,
                                     candidates,
                                     problems,
                                     chosen,
                                     newest);
      }
    verdict = Utilities::MPI::broadcast(communicator, verdict, 0);
    AssertThrow(verdict[0].empty(), ExcMessage(verdict[0]));
    out << verdict[1];
    CheckpointMetadata metadata = CheckpointMetadata::from_json(verdict[3]);
    metadata.folder             = verdict[2];
    return metadata;
  }



  void
  Checkpointing::check_compatibility(const CheckpointMetadata &metadata) const
  {
    // Every entry that is in either list and differs, with both values.
    std::string differences;
    const auto  value_in = [](const auto &map, const std::string &entry) {
      const auto found = map.find(entry);
      return found == map.end() ? std::string("(not set)") :
                                   "'" + found->second + "'";
    };
    std::set<std::string> entries;
    for (const auto &[entry, value] : parameters)
      entries.insert(entry);
    for (const auto &[entry, value] : metadata.parameters)
      if (!may_change_on_resume(entry))
        entries.insert(entry);
    for (const auto &entry : entries)
      if (value_in(parameters, entry) != value_in(metadata.parameters, entry))
        differences
          += "\n  " + entry + " = " + value_in(metadata.parameters, entry)
             + " in the checkpoint, " + value_in(parameters, entry) + " now";
    AssertThrow(differences.empty(),
                ExcMessage(
                  "Checkpoint/Resume from checkpoint = true: the checkpoint "
                  "in "
                  + metadata.folder
                  + " was written by a run of another problem (mesh, "
                    "discretisation or physics):"
                  + differences
                  + "\nResume with the parameters of that run (only the "
                    "sections Output, Checkpoint and Solver and Time/End time "
                    "may change), or start afresh without resuming."));
  }
} // namespace VPContact
