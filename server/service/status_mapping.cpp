// relmap's codes are gRPC's canonical codes by construction; a reason travels as
// AIP-193's google.rpc.ErrorInfo inside a google.rpc.Status in the status details.
#include "service/status_mapping.h"

#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"
#include "relmap/v1/error_reason.pb.h"

namespace relmap::service {
namespace {

v1::ErrorReason ToProto(ErrorReason reason) {
  switch (reason) {
    case ErrorReason::kFrameGone:
      return v1::FRAME_GONE;
    case ErrorReason::kSessionOwnedElsewhere:
      return v1::SESSION_OWNED_ELSEWHERE;
    case ErrorReason::kBusy:
      return v1::BUSY;
    case ErrorReason::kNone:
      break;
  }
  return v1::ERROR_REASON_UNSPECIFIED;
}

}  // namespace

grpc::Status ToGrpcStatus(const Status& status) {
  if (status.ok()) return grpc::Status::OK;
  const auto code = static_cast<grpc::StatusCode>(status.code());
  if (status.reason() == ErrorReason::kNone) return {code, status.message()};
  google::rpc::ErrorInfo info;
  info.set_reason(v1::ErrorReason_Name(ToProto(status.reason())));
  info.set_domain(kErrorDomain);
  info.mutable_metadata()->insert(status.metadata().begin(), status.metadata().end());
  google::rpc::Status details;
  details.set_code(static_cast<int>(code));
  details.set_message(status.message());
  details.add_details()->PackFrom(info);
  return {code, status.message(), details.SerializeAsString()};
}

}  // namespace relmap::service
