// How relmap-robot pushes: one interface in front of an arm (a user command, a robot
// controller over TCP, the simulator). A driver gets the target and reports whether the push
// happened.
#pragma once

#include <optional>
#include <string>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"
#include "robot_messages.pb.h"

namespace relmap::robot {

enum class PushResult { kDone, kFailed, kUnreachable };

struct PushOutcome {
  PushResult result = PushResult::kFailed;
  // The driver's own label (e.g. from haptics); unset: the change detector decides.
  std::optional<v1::Label> label;
  std::string message;
};

class PusherDriver {
 public:
  virtual ~PusherDriver() = default;
  // Pushes `target`. An error (the driver crashed, hung or answered garbage) is not a
  // push outcome: the caller treats it as a failed push it must not learn from.
  virtual StatusOr<PushOutcome> Push(const DriverRequest& target) = 0;
};

// The target a driver gets for supervoxel `target` of `maps`; the approach is the
// viewing ray to the centroid with its camera-vertical (y) part removed, normalised
// (along z when the centroid lies on the camera's vertical axis).
DriverRequest MakeDriverRequest(const std::string& session_id, const v1::ComputeMapsResponse& maps,
                                const v1::Supervoxel& target, int iteration, int attempt);

// `target` as one line of JSON, every field present, with the proto's field names: what
// an exec driver reads and a dry run prints.
std::string DriverRequestJson(const DriverRequest& target);

// `json` as a driver's answer (a DriverResult JSON object, e.g.
// {"result": "done", "label": "moved"}); INVALID_ARGUMENT saying what is wrong.
StatusOr<PushOutcome> ParseDriverResult(const std::string& json);

// "done", "failed", "unreachable".
const char* PushResultName(PushResult result);

}  // namespace relmap::robot
