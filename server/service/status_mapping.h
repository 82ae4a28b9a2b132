// The one place where relmap's Status becomes a gRPC status (same canonical codes).
#pragma once

#include <grpcpp/support/status.h>

#include "common/status.h"

namespace relmap::service {

// The google.rpc.ErrorInfo domain of relmap-server's reasons.
inline constexpr char kErrorDomain[] = "relmap.v1";

// The gRPC status of `status`: its code and message, and when it has a reason, a
// google.rpc.Status in the error details whose one detail is a google.rpc.ErrorInfo
// {reason: the relmap.v1.ErrorReason's name, domain: kErrorDomain, metadata}.
grpc::Status ToGrpcStatus(const Status& status);

}  // namespace relmap::service
