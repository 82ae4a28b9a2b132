// Where relmap-sim and relmap-robot find the relmap-server they start.
#include "server_binary.h"

#include <unistd.h>

#include <filesystem>
#include <vector>

namespace relmap::client {

StatusOr<std::string> FindServerBinary(const std::string& flag) {
  if (!flag.empty()) {
    if (::access(flag.c_str(), X_OK) == 0) return flag;
    return NotFoundError("--server-binary " + flag + " is not an executable file");
  }
  std::vector<std::string> candidates;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) candidates.push_back((self.parent_path() / "relmap-server").string());
#ifdef RELMAP_SERVER_BINARY
  candidates.emplace_back(RELMAP_SERVER_BINARY);
#endif
  std::string looked;
  for (const std::string& candidate : candidates) {
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    if (!looked.empty()) looked += ", ";
    looked += candidate;
  }
  return NotFoundError("no relmap-server found (looked at " + looked +
                       "); give --server-binary or --server");
}

}  // namespace relmap::client
