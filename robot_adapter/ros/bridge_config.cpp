#include "bridge_config.h"

#include <cmath>

namespace relmap::ros_bridge {
namespace {

Status CheckRange(const char* axis, float min, float max) {
  if (!std::isfinite(min) || !std::isfinite(max) || !(min < max)) {
    return InvalidArgumentError(std::string("~workspace: min_") + axis + " (" +
                                std::to_string(min) + ") must be below max_" + axis + " (" +
                                std::to_string(max) + ")");
  }
  return OkStatus();
}

}  // namespace

Status ValidateBridgeConfig(const BridgeConfig& config) {
  const std::string& address = config.client.address;
  const std::size_t colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == address.size()) {
    return InvalidArgumentError("~server: \"" + address + "\" is not host:port");
  }
  if (config.client.deadline.count() <= 0) {
    return InvalidArgumentError("~deadline_seconds must be positive");
  }
  if (config.session_id.empty() != config.session_token.empty()) {
    return InvalidArgumentError(
        "~session_id and ~session_token go together: set both to resume a session, neither "
        "to create one");
  }
  if (config.session.has_workspace()) {
    const v1::WorkspaceBox& box = config.session.workspace();
    for (const Status& status :
         {CheckRange("x", box.min_x(), box.max_x()), CheckRange("y", box.min_y(), box.max_y()),
          CheckRange("z", box.min_z(), box.max_z())}) {
      if (!status.ok()) return status;
    }
  }
  if (config.max_pushes < 0) {
    return InvalidArgumentError("~max_pushes must be 0 (no limit) or more, not " +
                                std::to_string(config.max_pushes));
  }
  if (config.frames_kept < 1) {
    return InvalidArgumentError("~frames_kept must be at least 1, not " +
                                std::to_string(config.frames_kept));
  }
  return OkStatus();
}

}  // namespace relmap::ros_bridge
