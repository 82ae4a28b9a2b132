// A gRPC call's status as relmap's Status, the call named in the message: how the
// programs over the client library (relmap-sim, relmap-robot) report a failed call.
#pragma once

#include <grpcpp/support/status.h>

#include <string>
#include <string_view>

#include "common/status.h"

namespace relmap::client {

// gRPC's codes are the canonical ones that StatusCode numbers alike.
inline Status FromGrpc(const grpc::Status& status, std::string_view call) {
  if (status.ok()) return OkStatus();
  return Status(static_cast<StatusCode>(status.error_code()),
                std::string(call) + ": " + status.error_message());
}

}  // namespace relmap::client
