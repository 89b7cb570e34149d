// A folder claimed by the run that writes into it: an flock() on a lock file
// of this program's, which the kernel releases when the process ends.
#include <vpcontact/app/folder_lock.h>

#include <deal.II/base/exceptions.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <sstream>
#include <string>
#include <sys/file.h>
#include <unistd.h>
#include <vector>

namespace VPContact
{
  const std::string FolderLock::header
    = "vpcontact run lock: the run below writes into this folder; the "
      "operating system releases the lock when it ends.";

  namespace
  {
    // What a lock file says of the run that holds the lock: its process id
    // and host, and when it started.
    std::string
    holder_text()
    {
      char host[256] = {};
      if (gethostname(host, sizeof(host) - 1) != 0)
        std::strcpy(host, "unknown-host");
      const std::time_t now = std::time(nullptr);
      std::tm           local{};
      localtime_r(&now, &local);
      char when[64] = {};
      std::strftime(when, sizeof(when), "%Y-%m-%d %H:%M:%S %Z", &local);
      return FolderLock::header + "\n" + std::to_string(getpid()) + "@" + host
             + "\nstarted " + when + "\n";
    }

    // The lines of the lock file open as @p descriptor.
    std::vector<std::string>
    lock_file_lines(const int descriptor)
    {
      std::string   text(4096, '\0');
      const ssize_t n = pread(descriptor, text.data(), text.size(), 0);
      text.resize(n > 0 ? n : 0);
      std::istringstream       in(text);
      std::vector<std::string> lines;
      for (std::string line; std::getline(in, line);)
        lines.push_back(line);
      return lines;
    }

    // "the run PID@HOST, started WHEN", from the lock file of the holder.
    std::string
    holder_of(const int descriptor)
    {
      const std::vector<std::string> lines = lock_file_lines(descriptor);
      // The holder may have the lock and not yet have written its name.
      if (lines.size() < 2 || lines[1].empty())
        return "a run that has not written its name into the lock file yet";
      return "the run " + lines[1] + (lines.size() > 2 ? ", " + lines[2] : "");
    }
  } // namespace



  FolderLock::FolderLock(const std::string &lock_file,
                         const std::string &folder_description)
  {
    // O_CLOEXEC: a program this run may start does not inherit the claim.
    descriptor = ::open(lock_file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    AssertThrow(descriptor >= 0,
                dealii::ExcMessage("cannot create the lock file " + lock_file
                                   + " (" + std::strerror(errno)
                                   + "). Give a folder that can be written."));
    // A file of that name that is not empty and was not written by this
    // program is the user's: it is neither locked nor overwritten.
    const std::vector<std::string> lines = lock_file_lines(descriptor);
    if (!lines.empty() && lines[0] != header)
      {
        release();
        AssertThrow(false,
                    dealii::ExcMessage(
                      "the file " + lock_file
                      + " exists and was not written by vpcontact, which "
                        "keeps its lock there. Move that file away."));
      }
    if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
      {
        not_locked(errno, lock_file, folder_description);
        return;
      }
    const std::string text    = holder_text();
    const bool        written = ::ftruncate(descriptor, 0) == 0
                         && ::pwrite(descriptor, text.data(), text.size(), 0)
                              == static_cast<ssize_t>(text.size());
    if (!written)
      {
        const std::string reason = std::strerror(errno);
        release();
        AssertThrow(false,
                    dealii::ExcMessage("cannot write the lock file " + lock_file
                                       + " (" + reason
                                       + "). Give a folder that can be "
                                         "written."));
      }
  }



  void
  FolderLock::not_locked(const int          error,
                         const std::string &lock_file,
                         const std::string &folder_description)
  {
    if (error == EWOULDBLOCK)
      {
        const std::string holder = holder_of(descriptor);
        release();
        AssertThrow(false,
                    dealii::ExcMessage(
                      folder_description
                      + " is in use by another run of vpcontact (" + holder
                      + "; its lock file is " + lock_file
                      + "). Two runs writing into one folder overwrite "
                        "each other's fields, tables and checkpoints. "
                        "Wait until that run has ended, or give another "
                        "folder."));
      }
    // No locks on this file system: the run goes on unprotected.
    release();
    unsupported_note = "the file system of " + lock_file
                       + " does not support locks (" + std::strerror(error)
                       + "): a second run writing into the same folder is "
                         "not detected.";
  }



  void
  FolderLock::release()
  {
    // Closing the only descriptor of the file releases the lock.
    if (descriptor >= 0)
      ::close(descriptor);
    descriptor = -1;
  }



  FolderLock::~FolderLock()
  {
    release();
  }



  const std::string &
  FolderLock::note() const
  {
    return unsupported_note;
  }
} // namespace VPContact
