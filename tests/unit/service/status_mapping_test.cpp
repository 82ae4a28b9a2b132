// relmap's Status -> grpc::Status at the service edge: the code and message as they
// are, and a reason that reaches the client library intact (Status -> grpc::Status ->
// reason) as AIP-193 details that any gRPC client can read.
#include "service/status_mapping.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

#include "error_reason.h"
#include "google/rpc/status.pb.h"

namespace relmap::service {
namespace {

TEST(StatusMapping, KeepsTheCodeAndTheMessage) {
  const grpc::Status mapped =
      ToGrpcStatus(FailedPreconditionError("frame 3 of session ab is unknown")
                       .WithReason(ErrorReason::kFrameGone));
  EXPECT_EQ(mapped.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(mapped.error_message(), "frame 3 of session ab is unknown");
}

TEST(StatusMapping, EveryReasonReachesTheClientAsTheProtoValueOfTheSameName) {
  const std::pair<ErrorReason, v1::ErrorReason> reasons[] = {
      {ErrorReason::kFrameGone, v1::FRAME_GONE},
      {ErrorReason::kSessionOwnedElsewhere, v1::SESSION_OWNED_ELSEWHERE},
      {ErrorReason::kBusy, v1::BUSY},
  };
  for (const auto& [reason, expected] : reasons) {
    const grpc::Status mapped =
        ToGrpcStatus(Status(StatusCode::kUnavailable, "").WithReason(reason));
    EXPECT_EQ(client::ReasonOf(mapped), expected) << v1::ErrorReason_Name(expected);
  }
}

TEST(StatusMapping, TheMetadataReachesTheClient) {
  const grpc::Status mapped = ToGrpcStatus(
      Status(StatusCode::kUnavailable, "session 's' is owned by server 'b'")
          .WithReason(ErrorReason::kSessionOwnedElsewhere, {{"sessionId", "s"}, {"owner", "b"}}));
  const std::optional<google::rpc::ErrorInfo> info = client::ErrorInfoOf(mapped);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->reason(), "SESSION_OWNED_ELSEWHERE");
  EXPECT_EQ(info->domain(), "relmap.v1");
  EXPECT_EQ(Status::Metadata(info->metadata().begin(), info->metadata().end()),
            (Status::Metadata{{"sessionId", "s"}, {"owner", "b"}}));
}

// What grpcurl and other gRPC clients decode: a google.rpc.Status that repeats the
// code and message, and holds the ErrorInfo as an Any of googleapis' type URL.
TEST(StatusMapping, TheDetailsAreAGoogleRpcStatusWithAnErrorInfo) {
  const grpc::Status mapped =
      ToGrpcStatus(ResourceExhaustedError("busy").WithReason(ErrorReason::kBusy));
  google::rpc::Status details;
  ASSERT_TRUE(details.ParseFromString(mapped.error_details()));
  EXPECT_EQ(details.code(), static_cast<int>(grpc::StatusCode::RESOURCE_EXHAUSTED));
  EXPECT_EQ(details.message(), "busy");
  ASSERT_EQ(details.details_size(), 1);
  EXPECT_EQ(details.details(0).type_url(), "type.googleapis.com/google.rpc.ErrorInfo");
}

TEST(StatusMapping, AnErrorWithoutAReasonHasNoDetails) {
  const grpc::Status mapped = ToGrpcStatus(InvalidArgumentError("no feature vector"));
  EXPECT_EQ(mapped.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_TRUE(mapped.error_details().empty());
  EXPECT_EQ(client::ReasonOf(mapped), v1::ERROR_REASON_UNSPECIFIED);
}

TEST(StatusMapping, OkIsOk) { EXPECT_TRUE(ToGrpcStatus(OkStatus()).ok()); }

}  // namespace
}  // namespace relmap::service
