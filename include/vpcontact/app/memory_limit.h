// What memory a process of this program may really use: the machine's
// physical memory, the limit of its control group, and its own resource
// limits (ulimit -v, ulimit -d).
#ifndef vpcontact_memory_limit_h
#define vpcontact_memory_limit_h

#include <string>

namespace VPContact
{
  /// A number of bytes that may still be used, the limit it comes from as
  /// set (for messages; infinite where there is none) and what sets it
  /// ("the machine's physical memory", "... ulimit -v ...").
  struct MemoryLimit
  {
    double      bytes;
    double      limit;
    std::string source;
    /// Whether it is the machine's physical memory (no other limit).
    bool physical = false;
  };

  /**
   * The memory the processes of this machine share: the smaller of its
   * physical memory and the limit of this process's control group (cgroup
   * v2 memory.max of its group and the groups above it, or v1
   * memory.limit_in_bytes), which the ranks of a job usually share.
   */
  MemoryLimit
  node_memory_limit();

  /**
   * What this process may still allocate under its own limits, RLIMIT_AS
   * (ulimit -v) and RLIMIT_DATA (ulimit -d), less the address space and data
   * it already uses; infinite bytes if neither is set.
   */
  MemoryLimit
  process_memory_limit();
} // namespace VPContact

#endif
