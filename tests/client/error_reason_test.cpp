// How the client library reads a failed call's reason: from the error details only,
// never from the message.
#include "error_reason.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "client/reasoned_status.h"

namespace relmap::client {
namespace {

using testing::ReasonedStatus;

TEST(ReasonOf, IsTheErrorInfosReasonWhateverTheMessageSays) {
  const grpc::Status status =
      ReasonedStatus(grpc::StatusCode::FAILED_PRECONDITION,
                     "session ab has learned samples already", "FRAME_GONE");
  EXPECT_EQ(ReasonOf(status), v1::FRAME_GONE);
}

TEST(ReasonOf, IsUnspecifiedForTheRightTextWithoutDetails) {
  const grpc::Status status(grpc::StatusCode::FAILED_PRECONDITION,
                            "frame 17 of session ab is unknown or no longer cached");
  EXPECT_EQ(ReasonOf(status), v1::ERROR_REASON_UNSPECIFIED);
}

TEST(ReasonOf, IsUnspecifiedForAReasonThisBuildDoesNotKnow) {
  EXPECT_EQ(ReasonOf(ReasonedStatus(grpc::StatusCode::UNAVAILABLE, "", "MOON_IN_THE_WAY")),
            v1::ERROR_REASON_UNSPECIFIED);
}

TEST(ReasonOf, IsUnspecifiedForAReasonOfAnotherDomain) {
  EXPECT_EQ(ReasonOf(ReasonedStatus(grpc::StatusCode::RESOURCE_EXHAUSTED, "", "BUSY",
                                    "pubsub.googleapis.com")),
            v1::ERROR_REASON_UNSPECIFIED);
}

TEST(ReasonOf, IsUnspecifiedForDetailsThatAreNotAStatus) {
  const grpc::Status garbage(grpc::StatusCode::UNAVAILABLE, "", std::string("\xff\xff\xff", 3));
  EXPECT_EQ(ReasonOf(garbage), v1::ERROR_REASON_UNSPECIFIED);
  EXPECT_FALSE(ErrorInfoOf(garbage).has_value());
}

TEST(ErrorInfoOf, HasTheMetadata) {
  google::rpc::ErrorInfo info;
  info.set_reason("BUSY");
  info.set_domain("relmap.v1");
  (*info.mutable_metadata())["retryAfterMs"] = "100";
  google::rpc::Status details;
  details.add_details()->PackFrom(info);
  const std::optional<google::rpc::ErrorInfo> read = ErrorInfoOf(
      grpc::Status(grpc::StatusCode::RESOURCE_EXHAUSTED, "busy", details.SerializeAsString()));
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->metadata().at("retryAfterMs"), "100");
}

}  // namespace
}  // namespace relmap::client
