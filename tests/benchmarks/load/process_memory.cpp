// Reads the VmRSS and VmHWM lines of /proc/<pid>/status ("VmRSS:\t  1234 kB").
#include "process_memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace relmap::load {

StatusOr<ProcessMemory> ReadProcessMemory(pid_t pid) {
  const std::string path = "/proc/" + std::to_string(pid) + "/status";
  std::ifstream in(path);
  if (!in)
    return NotFoundError("cannot read " + path + ": is process " + std::to_string(pid) +
                         " running?");
  ProcessMemory memory;
  bool rss_seen = false;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string name;
    std::int64_t kib = 0;
    if (!(words >> name >> kib)) continue;
    if (name == "VmRSS:") {
      memory.rss_kib = kib;
      rss_seen = true;
    } else if (name == "VmHWM:") {
      memory.peak_rss_kib = kib;
    }
  }
  // A zombie has a status file without memory lines.
  if (!rss_seen) return NotFoundError(path + " has no VmRSS line: the process has exited");
  return memory;
}

}  // namespace relmap::load
