// Reads AIP-193 error details: a google.rpc.Status in grpc::Status::error_details().
#include "error_reason.h"

#include "google/rpc/status.pb.h"

namespace relmap::client {

std::optional<google::rpc::ErrorInfo> ErrorInfoOf(const grpc::Status& status) {
  if (status.ok() || status.error_details().empty()) return std::nullopt;
  google::rpc::Status details;
  if (!details.ParseFromString(status.error_details())) return std::nullopt;
  for (const google::protobuf::Any& detail : details.details()) {
    google::rpc::ErrorInfo info;
    if (detail.UnpackTo(&info) && info.domain() == "relmap.v1") return info;
  }
  return std::nullopt;
}

v1::ErrorReason ReasonOf(const grpc::Status& status) {
  const std::optional<google::rpc::ErrorInfo> info = ErrorInfoOf(status);
  v1::ErrorReason reason = v1::ERROR_REASON_UNSPECIFIED;
  if (info.has_value() && v1::ErrorReason_Parse(info->reason(), &reason)) return reason;
  return v1::ERROR_REASON_UNSPECIFIED;
}

}  // namespace relmap::client
