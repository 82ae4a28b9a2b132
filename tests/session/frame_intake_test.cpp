// FrameIntake: admission first, then decoding; a busy intake says so, a cloud that
// does not decode keeps its decoder's status.
#include "session/intake/frame_intake.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <string>

namespace relmap::session {
namespace {

using std::chrono::milliseconds;
using std::chrono::system_clock;

// `width` x 1 points of the packed layout at z = 1 m, grey.
std::string PackedRow(std::uint32_t width) {
  std::string bytes;
  for (std::uint32_t i = 0; i < width; ++i) {
    const float xyz[3] = {0.01f * static_cast<float>(i), 0.0f, 1.0f};
    char point[16];
    std::memcpy(point, xyz, sizeof xyz);
    std::memset(point + 12, 128, 4);
    bytes.append(point, sizeof point);
  }
  return bytes;
}

FrameIntakeLimits Slots(std::size_t concurrent, std::size_t queued,
                        milliseconds max_wait = milliseconds(10000)) {
  FrameIntakeLimits limits;
  limits.concurrent = concurrent;
  limits.queued = queued;
  limits.max_wait = max_wait;
  return limits;
}

system_clock::time_point Soon() { return system_clock::now() + milliseconds(1000); }

TEST(FrameIntake, DecodesAPackedCloudUnderASlot) {
  FrameIntake intake({});
  const std::string bytes = PackedRow(4);
  FrameIntake::Taken taken = intake.Take(
      {.format = EncodedCloud::Format::kPacked, .bytes = bytes, .width = 4, .height = 1}, Soon());
  ASSERT_TRUE(taken.cloud.ok()) << taken.cloud.status().message();
  EXPECT_FALSE(taken.busy);
  EXPECT_LE(taken.cloud->admitted_at, taken.cloud->decoded_at);
}

TEST(FrameIntake, ARequestWithoutACloudIsInvalidNotBusy) {
  FrameIntake intake({});
  FrameIntake::Taken taken = intake.Take({}, Soon());
  EXPECT_EQ(taken.cloud.status().code(), StatusCode::kInvalidArgument);
  EXPECT_FALSE(taken.busy);
}

TEST(FrameIntake, BytesThatDoNotDecodeKeepTheDecodersStatus) {
  FrameIntake intake({});
  const std::string bytes = "not a pcd file";
  FrameIntake::Taken taken =
      intake.Take({.format = EncodedCloud::Format::kPcd, .bytes = bytes}, Soon());
  EXPECT_EQ(taken.cloud.status().code(), StatusCode::kInvalidArgument);
  EXPECT_FALSE(taken.busy);
}

TEST(FrameIntake, MorePointsThanTheLimitAreResourceExhaustedButNotBusy) {
  FrameIntakeLimits limits;
  limits.decode.max_points = 2;
  FrameIntake intake(limits);
  const std::string bytes = PackedRow(4);
  FrameIntake::Taken taken = intake.Take(
      {.format = EncodedCloud::Format::kPacked, .bytes = bytes, .width = 4, .height = 1}, Soon());
  EXPECT_EQ(taken.cloud.status().code(), StatusCode::kResourceExhausted);
  EXPECT_FALSE(taken.busy);  // repeating it would not help
}

TEST(FrameIntake, WithEverySlotTakenAndNoQueueItIsBusy) {
  FrameIntake intake(Slots(1, 0));
  const std::string bytes = PackedRow(4);
  const EncodedCloud cloud{
      .format = EncodedCloud::Format::kPacked, .bytes = bytes, .width = 4, .height = 1};
  FrameIntake::Taken first = intake.Take(cloud, Soon());
  ASSERT_TRUE(first.cloud.ok());
  FrameIntake::Taken second = intake.Take(cloud, Soon());
  EXPECT_TRUE(second.busy);
  EXPECT_EQ(second.cloud.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(second.cloud.status().message().find("busy: 1 clouds in progress"), std::string::npos);
}

TEST(FrameIntake, TheSlotIsFreedWithTheCloud) {
  FrameIntake intake(Slots(1, 0));
  const std::string bytes = PackedRow(4);
  const EncodedCloud cloud{
      .format = EncodedCloud::Format::kPacked, .bytes = bytes, .width = 4, .height = 1};
  { FrameIntake::Taken first = intake.Take(cloud, Soon()); }
  EXPECT_TRUE(intake.Take(cloud, Soon()).cloud.ok());
}

TEST(FrameIntake, AWaiterGivesUpAtTheLimitsMaximumWait) {
  FrameIntake intake(Slots(1, 1, milliseconds(50)));
  const std::string bytes = PackedRow(4);
  const EncodedCloud cloud{
      .format = EncodedCloud::Format::kPacked, .bytes = bytes, .width = 4, .height = 1};
  FrameIntake::Taken first = intake.Take(cloud, Soon());
  ASSERT_TRUE(first.cloud.ok());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(intake.Take(cloud, system_clock::now() + milliseconds(10000)).busy);
  EXPECT_LT(std::chrono::steady_clock::now() - start, milliseconds(5000));
}

}  // namespace
}  // namespace relmap::session
