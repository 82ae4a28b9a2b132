// The bridge's work without ROS: a session on a relmap server, the maps of every cloud
// as RViz messages, the outcomes posted for the frames it mapped, and the push loop's
// decisions. relmap_ros_bridge (ROS 1) is a thin node around it; a ROS 2 node would be
// another. Safe to call from several threads (the node's cloud worker and its service
// callbacks): state is guarded, calls to the server run outside the lock.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "bridge_config.h"
#include "cloud_message.h"
#include "common/status.h"

namespace relmap::client {
class RelevanceClient;
}

namespace relmap::ros_bridge {

// One cloud's maps, stamped with the cloud's stamp, in the frame it was sent in.
struct FrameMaps {
  std::uint64_t frame_id = 0;  // the server's, as PostOutcome takes it
  CloudMessage relevance;
  CloudMessage choice;
  std::optional<TargetPose> target;  // unset: nothing to push in this frame
  std::size_t supervoxels = 0;
  double server_ms = 0;  // the server's own time for the call
  // The cloud as sent (in the maps' frame, x y z rgb), when config.keep_sent_clouds.
  std::optional<CloudMessage> sent;
};

// An outcome the session learned.
struct OutcomeAnswer {
  Stamp stamp;        // of the frame's cloud
  std::string frame;  // the frame its maps were in
  std::uint64_t frame_id = 0;
  std::uint32_t supervoxel_id = 0;
  bool moved = false;  // the label learned (the change detector's, for an after cloud)
  bool from_after_cloud = false;
  std::uint64_t moveable_samples = 0;
  std::uint64_t non_moveable_samples = 0;
};

// What the user's push service answered (relmap_ros/Push): result "done", "failed" or
// "unreachable"; label "moved", "still" or "" (the change detector decides from the
// next cloud).
struct PushReply {
  std::string result;
  std::string label;
  std::string message;
};

// A cloud of the push loop: the outcome it carried as the last push's after cloud
// (when the push left the label to the change detector), and its maps. Each may have
// failed on its own: a learned outcome is reported even when the maps fail.
struct CloudStep {
  std::optional<StatusOr<OutcomeAnswer>> after_outcome;
  StatusOr<FrameMaps> maps = Status(StatusCode::kUnknown, "not mapped");
};

class Bridge {
 public:
  explicit Bridge(BridgeConfig config);
  ~Bridge();
  Bridge(const Bridge&) = delete;
  Bridge& operator=(const Bridge&) = delete;

  // Resumes the configured session, else creates one. The server's error otherwise.
  Status Start();
  const std::string& session_id() const { return session_id_; }
  const std::string& session_token() const { return session_token_; }
  const BridgeConfig& config() const { return config_; }

  // The maps of `cloud`, moved by `to_workspace` first when given; the frame is then
  // remembered (the last frames_kept) for outcomes that name its stamp.
  StatusOr<FrameMaps> Map(const CloudMessage& cloud,
                          const std::optional<RigidTransform>& to_workspace);
  // Supervoxel `supervoxel_id` of the frame stamped `stamp` moved (or not).
  // NOT_FOUND for a stamp of no remembered frame; the server's error otherwise
  // (INVALID_ARGUMENT for a supervoxel the frame does not have).
  StatusOr<OutcomeAnswer> PostLabel(Stamp stamp, std::uint32_t supervoxel_id, bool moved);
  // `after` is the scene after the push of the latest frame's target: the server's
  // change detector labels it. FAILED_PRECONDITION when that target has had its
  // outcome already, or no frame had a target.
  StatusOr<OutcomeAnswer> PostAfterCloud(const CloudMessage& after,
                                         const std::optional<RigidTransform>& to_workspace);

  // The push loop. A cloud: first the after cloud of the last push, when one is
  // awaited, then its maps.
  CloudStep OnCloud(const CloudMessage& cloud, const std::optional<RigidTransform>& to_workspace);
  // Whether the push loop pushes `maps`' target: it has one and pushes are left.
  // Counts the push.
  bool TakePush(const FrameMaps& maps);
  // The push service's answer for `maps`' target: posts its label, or awaits the next
  // cloud as the after cloud; a failed or unreachable push teaches nothing (nullopt).
  // INVALID_ARGUMENT for an answer that is none of these.
  StatusOr<std::optional<OutcomeAnswer>> OnPushReply(const FrameMaps& maps, const PushReply& reply);
  // Pushes sent by the push loop so far.
  int pushes() const;

 private:
  struct Frame {
    Stamp stamp;
    std::string frame;
    std::uint64_t frame_id = 0;
    std::optional<std::uint32_t> target;
    bool outcome_posted = false;
  };

  // The remembered frame stamped `stamp`, if any (under the lock).
  Frame* FindFrame(Stamp stamp);
  // PostOutcome with the after cloud for supervoxel `target` of `frame`.
  StatusOr<OutcomeAnswer> PostAfter(const Frame& frame, std::uint32_t target,
                                    const CloudMessage& after,
                                    const std::optional<RigidTransform>& to_workspace);

  const BridgeConfig config_;
  std::unique_ptr<client::RelevanceClient> client_;
  std::string session_id_;
  std::string session_token_;

  mutable std::mutex mutex_;
  std::deque<Frame> frames_;             // newest last
  std::optional<Stamp> awaiting_after_;  // the frame whose after cloud the loop waits for
  int pushes_ = 0;
};

}  // namespace relmap::ros_bridge
