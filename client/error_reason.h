// The machine-readable reason of a failed call: what a client decides by, instead
// of the message (proto/relmap/v1/error_reason.proto).
#pragma once

#include <grpcpp/support/status.h>

#include <optional>

#include "google/rpc/error_details.pb.h"
#include "relmap/v1/error_reason.pb.h"

namespace relmap::client {

// The google.rpc.ErrorInfo of domain "relmap.v1" that relmap-server put in the
// status's details (a serialized google.rpc.Status), if there is one.
std::optional<google::rpc::ErrorInfo> ErrorInfoOf(const grpc::Status& status);

// The reason of that ErrorInfo; ERROR_REASON_UNSPECIFIED without one, and for a
// reason this build does not know (a newer server's).
v1::ErrorReason ReasonOf(const grpc::Status& status);

}  // namespace relmap::client
