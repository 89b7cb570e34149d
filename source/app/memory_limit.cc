// What memory a process of this program may really use: the machine's
// physical memory, the limit of its control group, and its own resource
// limits.
#include <vpcontact/app/memory_limit.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace VPContact
{
  namespace
  {
    constexpr double unlimited = std::numeric_limits<double>::infinity();

    // The number in the file @p name ("max" or a missing file: unlimited).
    double
    limit_in_file(const std::string &name)
    {
      std::ifstream in(name);
      std::string   text;
      if (!(in >> text) || text == "max")
        return unlimited;
      try
        {
          return std::stod(text);
        }
      catch (const std::exception &)
        {
          return unlimited;
        }
    }

    // The smallest memory limit of the control group @p group (a path as
    // /proc/self/cgroup gives it) and of the groups above it, in the file
    // @p file under @p root. The group's own path may not be visible in a
    // container's mount namespace; the root of the mount (the container's
    // own group) is then the one that counts, and is looked at as well.
    double
    group_limit(const std::string &root,
                std::string        group,
                const std::string &file)
    {
      double limit = limit_in_file(root + "/" + file);
      while (!group.empty() && group != "/")
        {
          limit = std::min(limit, limit_in_file(root + group + "/" + file));
          group = group.substr(0, group.find_last_of('/'));
        }
      return limit;
    }

    // The cgroup limit of this process: v2 ("0::/path") or v1 (a line whose
    // controllers include "memory").
    double
    cgroup_limit()
    {
      std::ifstream in("/proc/self/cgroup");
      double        limit = unlimited;
      for (std::string line; std::getline(in, line);)
        {
          const auto first = line.find(':'), second = line.find(':', first + 1);
          if (first == std::string::npos || second == std::string::npos)
            continue;
          const std::string controllers
            = line.substr(first + 1, second - first - 1);
          const std::string group = line.substr(second + 1);
          if (controllers.empty())
            limit
              = std::min(limit,
                         group_limit("/sys/fs/cgroup", group, "memory.max"));
          else if (("," + controllers + ",").find(",memory,")
                   != std::string::npos)
            limit = std::min(limit,
                             group_limit("/sys/fs/cgroup/memory",
                                         group,
                                         "memory.limit_in_bytes"));
        }
      return limit;
    }

    // Field @p field (0: the whole address space, 5: data and stack) of
    // /proc/self/statm, in bytes.
    double
    used_bytes(const unsigned int field)
    {
      // /proc/self/statm holds page counts, one per field, in one line.
      std::ifstream       in("/proc/self/statm");
      std::vector<double> pages(field + 1, 0.);
      for (double &p : pages)
        if (!(in >> p))
          return 0.;
      return pages[field] * static_cast<double>(sysconf(_SC_PAGESIZE));
    }

    double
    resource_limit(const int resource)
    {
      struct rlimit limit;
      if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return unlimited;
      return static_cast<double>(limit.rlim_cur);
    }
  } // namespace



  MemoryLimit
  node_memory_limit()
  {
    const double physical = static_cast<double>(sysconf(_SC_PHYS_PAGES))
                            * static_cast<double>(sysconf(_SC_PAGESIZE));
    const double group = cgroup_limit();
    if (group < physical)
      return {group,
              group,
              "the memory limit of this process's control group (cgroup "
              "memory.max or memory.limit_in_bytes)"};
    return {physical, physical, "the machine's physical memory", true};
  }



  MemoryLimit
  process_memory_limit()
  {
    const double address_space      = resource_limit(RLIMIT_AS);
    const double data               = resource_limit(RLIMIT_DATA);
    const double free_address_space = address_space - used_bytes(0);
    const double free_data          = data - used_bytes(5);
    if (free_address_space <= free_data && address_space < unlimited)
      return {std::max(free_address_space, 0.),
              address_space,
              "this process's address-space limit (ulimit -v, RLIMIT_AS)"};
    if (data < unlimited)
      return {std::max(free_data, 0.),
              data,
              "this process's data limit (ulimit -d, RLIMIT_DATA)"};
    return {unlimited, unlimited, "no limit of this process"};
  }
} // namespace VPContact
