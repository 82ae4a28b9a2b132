// The push loop's decisions that need no server: when to push, and which answers of a
// push service are refused. (Posting, with a server, is ros_bridge_test's.)
#include <gtest/gtest.h>

#include "bridge.h"

namespace relmap::ros_bridge {
namespace {

FrameMaps WithTarget() {
  FrameMaps maps;
  maps.target = TargetPose{};
  maps.target->supervoxel_id = 4;
  return maps;
}

BridgeConfig PushLoop(int max_pushes) {
  BridgeConfig config;
  config.push_loop = true;
  config.max_pushes = max_pushes;
  return config;
}

TEST(BridgePushLoop, PushesTargetsUntilMaxPushes) {
  Bridge bridge(PushLoop(2));
  EXPECT_FALSE(bridge.TakePush(FrameMaps{})) << "no target, no push";
  EXPECT_TRUE(bridge.TakePush(WithTarget()));
  EXPECT_TRUE(bridge.TakePush(WithTarget()));
  EXPECT_FALSE(bridge.TakePush(WithTarget()));
  EXPECT_EQ(bridge.pushes(), 2);
}

TEST(BridgePushLoop, NeverPushesWhenTheLoopIsOff) {
  Bridge bridge(BridgeConfig{});
  EXPECT_FALSE(bridge.TakePush(WithTarget()));
  EXPECT_EQ(bridge.pushes(), 0);
}

TEST(BridgePushLoop, AFailedOrUnreachablePushTeachesNothing) {
  Bridge bridge(PushLoop(0));
  for (const char* result : {"failed", "unreachable"}) {
    StatusOr<std::optional<OutcomeAnswer>> outcome =
        bridge.OnPushReply(WithTarget(), {result, "moved", ""});
    ASSERT_TRUE(outcome.ok()) << outcome.status().message();
    EXPECT_FALSE(outcome->has_value()) << result;
  }
}

TEST(BridgePushLoop, RefusesAnswersThatAreNoneOfTheDocumentedOnes) {
  Bridge bridge(PushLoop(0));
  StatusOr<std::optional<OutcomeAnswer>> result = bridge.OnPushReply(WithTarget(), {"ok", "", ""});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().message(),
            "the push service answered result \"ok\", not done, failed or unreachable");
  StatusOr<std::optional<OutcomeAnswer>> label =
      bridge.OnPushReply(WithTarget(), {"done", "yes", ""});
  ASSERT_FALSE(label.ok());
  EXPECT_EQ(label.status().message(),
            "the push service answered label \"yes\", not moved, still or empty");
}

TEST(BridgePushLoop, ADonePushWithoutLabelAwaitsTheNextCloud) {
  Bridge bridge(PushLoop(0));
  StatusOr<std::optional<OutcomeAnswer>> outcome =
      bridge.OnPushReply(WithTarget(), {"done", "", ""});
  ASSERT_TRUE(outcome.ok()) << outcome.status().message();
  EXPECT_FALSE(outcome->has_value()) << "the next cloud is the after cloud";
}

TEST(BridgePushLoop, ALabelForAFrameTheBridgeDidNotMapIsNotFound) {
  Bridge bridge(PushLoop(0));
  FrameMaps maps = WithTarget();
  maps.target->stamp = {12, 5};
  StatusOr<std::optional<OutcomeAnswer>> outcome = bridge.OnPushReply(maps, {"done", "moved", ""});
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.status().code(), StatusCode::kNotFound);
  EXPECT_EQ(outcome.status().message(),
            "no frame stamped 12.000000005 among the last 0 maps of this bridge");
}

}  // namespace
}  // namespace relmap::ros_bridge
