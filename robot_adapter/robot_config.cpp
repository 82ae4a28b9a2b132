// Reading and checking relmap-robot's config file.
#include "robot_config.h"

#include <google/protobuf/util/json_util.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "openni2_source.h"
#include "yaml_json.h"

namespace relmap::robot {
namespace {

Status Invalid(const std::string& label, const std::string& what) {
  return InvalidArgumentError(label + ": " + what);
}

Status Validate(const RobotConfig& config, const std::string& label) {
  if (config.source().kind_case() == SourceConfig::KIND_NOT_SET) {
    return Invalid(label, R"(source: set "directory", "stdin", "tcp", "openni2" or "sim")");
  }
  if (config.source().has_tcp() && config.source().tcp().listen().empty()) {
    return Invalid(label, "source.tcp.listen is empty (host:port, e.g. \"0.0.0.0:5000\")");
  }
  if (config.source().has_openni2() && !OpenNI2Available()) {
    return Invalid(label,
                   "source.openni2: this build of relmap-robot has no OpenNI2 (its PCL was built "
                   "without it); stream the camera's frames with source.tcp or source.stdin");
  }
  if (config.source().has_directory() && config.source().directory().path().empty()) {
    return Invalid(label, "source.directory.path is empty");
  }
  if (config.source().has_sim() && config.source().sim().scene().empty()) {
    return Invalid(label, "source.sim.scene is empty");
  }
  if (config.driver().kind_case() == DriverConfig::KIND_NOT_SET) {
    return Invalid(label, R"(driver: set "exec", "tcp_json" or "sim")");
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
  }
  if (config.driver().has_tcp_json()) {
    const TcpJsonDriverConfig& tcp = config.driver().tcp_json();
    if (tcp.address().empty()) return Invalid(label, "driver.tcp_json.address is empty");
    if (tcp.connect_timeout_seconds() < 0 || tcp.timeout_seconds() < 0) {
      return Invalid(label, "driver.tcp_json: a timeout is negative");
    }
  }
  // A real arm is never sent a target without a box to keep it in.
  if (!config.driver().has_sim() && !config.has_workspace()) {
    return Invalid(label, "driver." +
                              std::string(config.driver().has_exec() ? "exec" : "tcp_json") +
                              " needs a \"workspace\" box");
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
  if (config.driver().has_tcp_json()) {
    TcpJsonDriverConfig* tcp = config.mutable_driver()->mutable_tcp_json();
    if (!tcp->has_timeout_seconds()) tcp->set_timeout_seconds(kDefaultDriverTimeoutSeconds);
    if (!tcp->has_connect_timeout_seconds()) {
      tcp->set_connect_timeout_seconds(kDefaultConnectTimeoutSeconds);
    }
  }
  if (config.source().has_openni2() && !config.source().openni2().has_frame_timeout_seconds()) {
    config.mutable_source()->mutable_openni2()->set_frame_timeout_seconds(
        kDefaultFrameTimeoutSeconds);
  }
  return config;
}

StatusOr<RobotConfig> ParseRobotConfigYaml(std::string_view yaml, const std::string& label) {
  StatusOr<std::string> json = YamlToJson(yaml, label);
  if (!json.ok()) return json.status();
  return ParseRobotConfig(*json, label);
}

StatusOr<RobotConfig> ReadRobotConfig(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFoundError("cannot read config file " + path);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".yaml" || extension == ".yml") return ParseRobotConfigYaml(text, path);
  return ParseRobotConfig(text, path);
}

bool InWorkspace(const v1::WorkspaceBox& box, double x, double y, double z) {
  return x >= box.min_x() && x <= box.max_x() && y >= box.min_y() && y <= box.max_y() &&
         z >= box.min_z() && z <= box.max_z();
}

}  // namespace relmap::robot
