// relmap's codes are gRPC's canonical codes by construction.
#include "service/status_mapping.h"

namespace relmap::service {

grpc::Status ToGrpcStatus(const Status& status) {
  if (status.ok()) return grpc::Status::OK;
  return {static_cast<grpc::StatusCode>(status.code()), status.message()};
}

}  // namespace relmap::service
