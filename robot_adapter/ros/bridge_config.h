// What relmap_ros_bridge is told (ROS parameters, or a ROS 2 node's): the server, the
// session, the workspace, the push loop. Defaults are the ones docs/ros.md lists;
// ValidateBridgeConfig is the one place that says what is acceptable.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "client_options.h"
#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::ros_bridge {

struct BridgeConfig {
  // address, TLS root certificates, deadline and retries of every call.
  client::ClientOptions client;
  // For servers started with an admin key (CreateSession needs it).
  std::string admin_key;
  // An existing session to feed (both set), else a new one created with `session`.
  std::string session_id;
  std::string session_token;
  v1::SessionConfig session;
  // The frame clouds are moved into (tf2) before they are sent; empty: sent as they
  // come. The session's workspace box (session.workspace) is in this frame.
  std::string workspace_frame;
  // The user's push service is called with every target (the push loop).
  bool push_loop = false;
  // Pushes of the push loop before it stops calling; 0: no limit.
  int max_pushes = 0;
  // Frames whose maps ~post_outcome can still name: the server keeps 8 by default.
  int frames_kept = 8;
  // Each FrameMaps carries the cloud as it was sent (for recording a bag).
  bool keep_sent_clouds = false;
};

// OK, or INVALID_ARGUMENT naming the parameter (with the node's ~ prefix) and what is
// wrong with it.
Status ValidateBridgeConfig(const BridgeConfig& config);

}  // namespace relmap::ros_bridge
