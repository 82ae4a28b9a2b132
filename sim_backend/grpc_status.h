// A gRPC call's status as the runner's Status, the call named in the message.
#pragma once

#include <grpcpp/support/status.h>

#include <string>

#include "common/status.h"

namespace relmap::sim {

// gRPC's codes are the canonical ones that StatusCode numbers alike.
inline Status FromGrpc(const grpc::Status& status, const char* call) {
  if (status.ok()) return OkStatus();
  return Status(static_cast<StatusCode>(status.error_code()),
                std::string(call) + ": " + status.error_message());
}

}  // namespace relmap::sim
