// YAML config files as the JSON that the config parser reads, so that YAML and JSON
// configs share one schema (RobotConfig) and one set of checks.
#pragma once

#include <string>
#include <string_view>

#include "common/status.h"

namespace relmap::robot {

// The first (and only) document of `yaml` as JSON. A plain (unquoted) scalar that is a
// JSON number, true/false or null becomes that; every other scalar a string (quote
// "1" or "true" to have the string); mapping keys are strings. INVALID_ARGUMENT naming
// `label` and the line for malformed YAML, duplicate keys, non-scalar keys, several
// documents.
StatusOr<std::string> YamlToJson(std::string_view yaml, const std::string& label);

}  // namespace relmap::robot
