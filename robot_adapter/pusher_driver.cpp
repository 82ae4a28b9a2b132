// The target a driver gets and the answer it gives, as JSON: the exec and tcp-json
// drivers' common language.
#include "pusher_driver.h"

#include <google/protobuf/util/json_util.h>

#include <cmath>

namespace relmap::robot {

DriverRequest MakeDriverRequest(const std::string& session_id, const v1::ComputeMapsResponse& maps,
                                const v1::Supervoxel& target, int iteration, int attempt) {
  DriverRequest request;
  request.set_session(session_id);
  request.set_frame(maps.frame_id());
  request.set_supervoxel(target.id());
  *request.mutable_centroid() = target.centroid();
  *request.mutable_normal() = target.normal();
  // The camera's y axis points down: dropping it leaves the horizontal part of the
  // viewing ray for a level camera, which pushes the object away from the camera.
  const float x = target.centroid().x();
  const float z = target.centroid().z();
  const float length = std::hypot(x, z);
  request.mutable_approach()->set_x(length > 0 ? x / length : 0.0f);
  request.mutable_approach()->set_z(length > 0 ? z / length : 1.0f);
  request.set_iteration(static_cast<std::uint32_t>(iteration));
  request.set_attempt(static_cast<std::uint32_t>(attempt));
  return request;
}

std::string DriverRequestJson(const DriverRequest& target) {
  std::string json;
  google::protobuf::util::JsonPrintOptions options;
  options.always_print_primitive_fields = true;
  options.preserve_proto_field_names = true;
  (void)google::protobuf::util::MessageToJsonString(target, &json, options);
  return json;
}

const char* PushResultName(PushResult result) {
  switch (result) {
    case PushResult::kDone:
      return "done";
    case PushResult::kFailed:
      return "failed";
    case PushResult::kUnreachable:
      return "unreachable";
  }
  return "failed";
}

StatusOr<PushOutcome> ParseDriverResult(const std::string& json) {
  DriverResult result;
  google::protobuf::util::JsonParseOptions options;
  options.ignore_unknown_fields = false;
  const auto parsed = google::protobuf::util::JsonStringToMessage(json, &result, options);
  const std::string quoted = json.size() > 200 ? json.substr(0, 200) + "..." : json;
  if (!parsed.ok()) {
    return InvalidArgumentError("driver answer is not a DriverResult JSON object (" +
                                std::string(parsed.message()) + "): " + quoted);
  }
  PushOutcome outcome;
  outcome.message = result.message();
  if (result.result() == "done") {
    outcome.result = PushResult::kDone;
  } else if (result.result() == "failed") {
    outcome.result = PushResult::kFailed;
  } else if (result.result() == "unreachable") {
    outcome.result = PushResult::kUnreachable;
  } else {
    return InvalidArgumentError(R"(driver answer: "result" must be "done", "failed" or )" +
                                std::string(R"("unreachable", not ")") + result.result() + "\"");
  }
  if (result.label() == "moved") {
    outcome.label = v1::LABEL_MOVEABLE;
  } else if (result.label() == "still") {
    outcome.label = v1::LABEL_NOT_MOVEABLE;
  } else if (!result.label().empty()) {
    return InvalidArgumentError(R"(driver answer: "label" must be "moved" or "still", not ")" +
                                result.label() + "\"");
  }
  if (outcome.label && outcome.result != PushResult::kDone) {
    return InvalidArgumentError("driver answer: a label with result \"" + result.result() +
                                "\" (only a done push has one)");
  }
  return outcome;
}

}  // namespace relmap::robot
