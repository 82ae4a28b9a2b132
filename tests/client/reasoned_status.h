// gRPC statuses with AIP-193 details as relmap-server sends them, built by hand so
// that the client's reading is tested apart from the server's writing.
#pragma once

#include <grpcpp/support/status.h>

#include <string>

#include "google/rpc/error_details.pb.h"
#include "google/rpc/status.pb.h"

namespace relmap::client::testing {

// `code` and `message` with a google.rpc.Status whose one detail is an ErrorInfo of
// `reason` in `domain`.
inline grpc::Status ReasonedStatus(grpc::StatusCode code, const std::string& message,
                                   const std::string& reason,
                                   const std::string& domain = "relmap.v1") {
  google::rpc::ErrorInfo info;
  info.set_reason(reason);
  info.set_domain(domain);
  google::rpc::Status details;
  details.set_code(static_cast<int>(code));
  details.set_message(message);
  details.add_details()->PackFrom(info);
  return grpc::Status(code, message, details.SerializeAsString());
}

}  // namespace relmap::client::testing
