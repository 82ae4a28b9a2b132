// Reading and checking relmap-robot's config file.
#include "robot_config.h"

#include <google/protobuf/util/json_util.h>

#include <fstream>
#include <iterator>

namespace relmap::robot {
namespace {

Status Invalid(const std::string& label, const std::string& what) {
  return InvalidArgumentError(label + ": " + what);
}

Status Validate(const RobotConfig& config, const std::string& label) {
  if (config.source().kind_case() == SourceConfig::KIND_NOT_SET) {
    return Invalid(label, "source: set \"directory\" or \"sim\"");
  }
  if (config.source().has_directory() && config.source().directory().path().empty()) {
    return Invalid(label, "source.directory.path is empty");
  }
  if (config.source().has_sim() && config.source().sim().scene().empty()) {
    return Invalid(label, "source.sim.scene is empty");
  }
  if (config.driver().kind_case() == DriverConfig::KIND_NOT_SET) {
    return Invalid(label, "driver: set \"exec\" or \"sim\"");
  }
  if (config.driver().has_sim() && !config.source().has_sim()) {
    return Invalid(label, "driver.sim pushes in the simulator: it needs source.sim");
  }
  if (config.driver().has_exec()) {
    if (config.driver().exec().command().empty())
      return Invalid(label, "driver.exec.command is empty");
    if (config.driver().exec().timeout_seconds() < 0) {
      return Invalid(label, "driver.exec.timeout_seconds is negative");
    }
    // A real arm is never sent a target without a box to keep it in.
    if (!config.has_workspace()) return Invalid(label, "driver.exec needs a \"workspace\" box");
  }
  if (config.has_workspace()) {
    const v1::WorkspaceBox& w = config.workspace();
    if (!(w.min_x() < w.max_x() && w.min_y() < w.max_y() && w.min_z() < w.max_z())) {
      return Invalid(label, "workspace: every min_* must be below its max_*");
    }
  }
  if (config.has_max_pushes() && config.max_pushes() == 0) {
    return Invalid(label, "max_pushes is 0: nothing to do");
  }
  if (!config.session_id().empty() && config.has_session()) {
    return Invalid(label,
                   "session_id resumes a session; \"session\" configures a new one: not both");
  }
  return OkStatus();
}

}  // namespace

StatusOr<RobotConfig> ParseRobotConfig(std::string_view json, const std::string& label) {
  RobotConfig config;
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = false;
  const auto parsed = google::protobuf::util::JsonStringToMessage(
      google::protobuf::StringPiece(json.data(), json.size()), &config, options);
  if (!parsed.ok()) {
    return Invalid(label, "not a valid config (JSON of robot_messages.proto's RobotConfig): " +
                              std::string(parsed.message()));
  }
  if (Status valid = Validate(config, label); !valid.ok()) return valid;
  if (!config.has_max_pushes()) config.set_max_pushes(kDefaultMaxPushes);
  if (!config.has_max_iterations()) config.set_max_iterations(4 * config.max_pushes());
  if (!config.has_retries()) config.set_retries(kDefaultRetries);
  if (config.driver().has_exec() && !config.driver().exec().has_timeout_seconds()) {
    config.mutable_driver()->mutable_exec()->set_timeout_seconds(kDefaultDriverTimeoutSeconds);
  }
  return config;
}

StatusOr<RobotConfig> ReadRobotConfig(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFoundError("cannot read config file " + path);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return ParseRobotConfig(text, path);
}

bool InWorkspace(const v1::WorkspaceBox& box, double x, double y, double z) {
  return x >= box.min_x() && x <= box.max_x() && y >= box.min_y() && y <= box.max_y() &&
         z >= box.min_z() && z <= box.max_z();
}

}  // namespace relmap::robot
