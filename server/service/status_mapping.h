// The one place where relmap's Status becomes a gRPC status (same canonical codes).
#pragma once

#include <grpcpp/support/status.h>

#include "common/status.h"

namespace relmap::service {

grpc::Status ToGrpcStatus(const Status& status);

}  // namespace relmap::service
