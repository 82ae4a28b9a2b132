// What ValidateBridgeConfig refuses, and that it names the parameter.
#include "bridge_config.h"

#include <gtest/gtest.h>

namespace relmap::ros_bridge {
namespace {

std::string Refusal(const BridgeConfig& config) {
  const Status status = ValidateBridgeConfig(config);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  return status.message();
}

TEST(ValidateBridgeConfig, AcceptsTheDefaults) { EXPECT_TRUE(ValidateBridgeConfig({}).ok()); }

TEST(ValidateBridgeConfig, NamesAnAddressWithoutPort) {
  BridgeConfig config;
  config.client.address = "localhost";
  EXPECT_EQ(Refusal(config), "~server: \"localhost\" is not host:port");
}

TEST(ValidateBridgeConfig, WantsSessionIdAndTokenTogether) {
  BridgeConfig config;
  config.session_id = "abc";
  EXPECT_NE(Refusal(config).find("~session_id and ~session_token go together"), std::string::npos);
}

TEST(ValidateBridgeConfig, RefusesAnEmptyWorkspaceAxis) {
  BridgeConfig config;
  v1::WorkspaceBox* box = config.session.mutable_workspace();
  box->set_min_x(-1);
  box->set_max_x(1);
  box->set_min_y(0.5F);
  box->set_max_y(0.5F);
  box->set_min_z(0);
  box->set_max_z(2);
  EXPECT_NE(Refusal(config).find("min_y"), std::string::npos);
}

TEST(ValidateBridgeConfig, RefusesNegativePushesAndNoFramesKept) {
  BridgeConfig pushes;
  pushes.max_pushes = -1;
  EXPECT_NE(Refusal(pushes).find("~max_pushes"), std::string::npos);
  BridgeConfig frames;
  frames.frames_kept = 0;
  EXPECT_NE(Refusal(frames).find("~frames_kept"), std::string::npos);
}

}  // namespace
}  // namespace relmap::ros_bridge
