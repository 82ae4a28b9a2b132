// relmap-robot's config file: JSON of RobotConfig (robot_messages.proto), or the same
// in YAML, checked in one place, defaults applied.
#pragma once

#include <string>
#include <string_view>

#include "common/status.h"
#include "robot_messages.pb.h"

namespace relmap::robot {

// Defaults of the optional fields.
inline constexpr unsigned kDefaultMaxPushes = 10;
inline constexpr unsigned kDefaultRetries = 2;  // the paper's
inline constexpr double kDefaultDriverTimeoutSeconds = 60;
inline constexpr double kDefaultConnectTimeoutSeconds = 5;
inline constexpr double kDefaultFrameTimeoutSeconds = 10;

// Parses and validates `json`; INVALID_ARGUMENT naming `label` and the field.
StatusOr<RobotConfig> ParseRobotConfig(std::string_view json, const std::string& label);
// The same from YAML, turned into that JSON first (yaml_json.h).
StatusOr<RobotConfig> ParseRobotConfigYaml(std::string_view yaml, const std::string& label);
// The same from a file: YAML when it ends in .yaml or .yml, else JSON; NOT_FOUND when
// it cannot be read.
StatusOr<RobotConfig> ReadRobotConfig(const std::string& path);

// Whether `point` (camera frame) lies inside `box`, bounds included.
bool InWorkspace(const v1::WorkspaceBox& box, double x, double y, double z);

}  // namespace relmap::robot
