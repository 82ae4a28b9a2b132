// The target a driver gets.
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

}  // namespace relmap::robot
