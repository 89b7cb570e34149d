// A folder claimed by the run that writes into it: a lock that the operating
// system releases when the process ends, however it ends.
#ifndef vpcontact_folder_lock_h
#define vpcontact_folder_lock_h

#include <string>

namespace VPContact
{
  /**
   * The claim of one run on a folder it writes into (Output/Directory, or a
   * Checkpoint/Folder outside it). Two runs writing into one folder would
   * overwrite each other's fields, tables and checkpoints without a word,
   * so the second is refused.
   *
   * The claim is an flock() on a lock file of this program's
   * (.vpcontact-lock in the output folder), held from the constructor to
   * the destructor. The kernel drops the lock when the process ends, also
   * on a crash or SIGKILL: a stale lock file never blocks a later run or a
   * resume. The file itself stays; after taking the lock the run writes
   * its process id, host and start time into it, so that a refused run can
   * name the one that holds the folder.
   *
   * On a file system without locks (some parallel file systems mounted
   * without them) the claim is not possible; the run goes on and note()
   * says so.
   */
  class FolderLock
  {
  public:
    /**
     * Take the lock of @p lock_file, which is created if missing. Throws a
     * message naming @p folder_description (e.g. "this folder") and the run
     * that holds it if another process does, and one naming the file if it
     * exists but was not written by this program, or cannot be opened.
     */
    FolderLock(const std::string &lock_file,
               const std::string &folder_description);

    /// Releases the lock (the file stays).
    ~FolderLock();

    FolderLock(const FolderLock &) = delete;
    FolderLock &
    operator=(const FolderLock &)
      = delete;

    /// Empty, or why the folder could not be claimed (no locks there).
    const std::string &
    note() const;

    /// The first line of every lock file of this program.
    static const std::string header;

  private:
    /**
     * The lock was not taken, flock() said @p error: throw the message
     * naming the run that holds it, or, on a file system without locks,
     * give up the claim and keep a note.
     */
    void
    not_locked(const int          error,
               const std::string &lock_file,
               const std::string &folder_description);

    /// Close the lock file, which releases the lock.
    void
    release();

    int         descriptor = -1;
    std::string unsupported_note;
  };
} // namespace VPContact

#endif
