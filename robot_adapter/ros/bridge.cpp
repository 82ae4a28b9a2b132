#include "bridge.h"

#include <cstdio>
#include <utility>

#include "cloud_conversion.h"
#include "grpc_status.h"
#include "map_clouds.h"
#include "relevance_client.h"

namespace relmap::ros_bridge {
namespace {

std::string StampText(Stamp stamp) {
  char text[32];
  std::snprintf(text, sizeof text, "%u.%09u", stamp.sec, stamp.nsec);
  return text;
}

// The points of `cloud` as sent to the server: decoded, moved into the workspace.
StatusOr<pcd::Points> PointsToSend(const CloudMessage& cloud,
                                   const std::optional<RigidTransform>& to_workspace) {
  StatusOr<pcd::Points> points = DecodeCloudMessage(cloud);
  if (!points.ok()) return points.status();
  if (to_workspace) TransformPoints(*to_workspace, &*points);
  return points;
}

// `outcome` (its frame and supervoxel) as the server answered it.
OutcomeAnswer Answer(OutcomeAnswer outcome, const v1::PostOutcomeResponse& response,
                     bool from_after_cloud) {
  outcome.moved = response.label() == v1::LABEL_MOVEABLE;
  outcome.from_after_cloud = from_after_cloud;
  outcome.moveable_samples = response.stats().moveable_samples();
  outcome.non_moveable_samples = response.stats().non_moveable_samples();
  return outcome;
}

}  // namespace

Bridge::Bridge(BridgeConfig config)
    : config_(std::move(config)),
      client_(std::make_unique<client::RelevanceClient>(config_.client)) {
  if (!config_.admin_key.empty()) client_->set_admin_key(config_.admin_key);
}

Bridge::~Bridge() = default;

Status Bridge::Start() {
  if (!config_.session_id.empty()) {
    v1::GetSessionResponse session;
    const client::SessionHandle handle{config_.session_id, config_.session_token};
    Status status = client::FromGrpc(client_->GetSession(handle, &session), "GetSession");
    if (!status.ok()) return status;
    session_id_ = config_.session_id;
    session_token_ = config_.session_token;
    return OkStatus();
  }
  client::SessionHandle handle;
  Status status =
      client::FromGrpc(client_->CreateSession(config_.session, &handle), "CreateSession");
  if (!status.ok()) return status;
  session_id_ = handle.id;
  session_token_ = handle.token;
  return OkStatus();
}

StatusOr<FrameMaps> Bridge::Map(const CloudMessage& cloud,
                                const std::optional<RigidTransform>& to_workspace) {
  StatusOr<pcd::Points> points = PointsToSend(cloud, to_workspace);
  if (!points.ok()) return points.status();
  const std::string frame = to_workspace ? to_workspace->target_frame : cloud.frame_id;
  v1::ComputeMapsResponse response;
  Status status = client::FromGrpc(
      client_->ComputeMaps({session_id_, session_token_}, PackPoints(*points), &response),
      "ComputeMaps");
  if (!status.ok()) return status;

  FrameMaps maps;
  maps.frame_id = response.frame_id();
  maps.supervoxels = static_cast<std::size_t>(response.supervoxels_size());
  maps.server_ms = response.timings().total_ms();
  for (auto [kind, out] : {std::pair{client::MapKind::kRelevance, &maps.relevance},
                           std::pair{client::MapKind::kChoice, &maps.choice}}) {
    StatusOr<CloudMessage> map = MapCloud(*points, response, kind, frame, cloud.stamp);
    if (!map.ok()) return map.status();
    *out = std::move(*map);
  }
  maps.target = TargetOf(response, frame, cloud.stamp);
  if (config_.keep_sent_clouds) maps.sent = EncodeCloudMessage(*points, frame, cloud.stamp);

  std::lock_guard lock(mutex_);
  Frame remembered{cloud.stamp, frame, maps.frame_id, std::nullopt, false};
  if (maps.target) remembered.target = maps.target->supervoxel_id;
  frames_.push_back(std::move(remembered));
  while (frames_.size() > static_cast<std::size_t>(config_.frames_kept)) frames_.pop_front();
  return maps;
}

Bridge::Frame* Bridge::FindFrame(Stamp stamp) {
  for (Frame& frame : frames_) {
    if (frame.stamp == stamp) return &frame;
  }
  return nullptr;
}

StatusOr<OutcomeAnswer> Bridge::PostLabel(Stamp stamp, std::uint32_t supervoxel_id, bool moved) {
  Frame frame;
  {
    std::lock_guard lock(mutex_);
    const Frame* found = FindFrame(stamp);
    if (found == nullptr) {
      return NotFoundError("no frame stamped " + StampText(stamp) + " among the last " +
                           std::to_string(frames_.size()) + " maps of this bridge");
    }
    frame = *found;
  }
  v1::PostOutcomeResponse response;
  Status status = client::FromGrpc(
      client_->PostOutcome({session_id_, session_token_}, frame.frame_id, supervoxel_id,
                           moved ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE, "", &response),
      "PostOutcome");
  if (!status.ok()) return status;
  {
    std::lock_guard lock(mutex_);
    if (Frame* found = FindFrame(stamp); found != nullptr && found->target == supervoxel_id) {
      found->outcome_posted = true;
    }
  }
  return Answer({stamp, frame.frame, frame.frame_id, supervoxel_id}, response, false);
}

StatusOr<OutcomeAnswer> Bridge::PostAfter(const Frame& frame, std::uint32_t target,
                                          const CloudMessage& after,
                                          const std::optional<RigidTransform>& to_workspace) {
  StatusOr<pcd::Points> points = PointsToSend(after, to_workspace);
  if (!points.ok()) return points.status();
  v1::PostOutcomeResponse response;
  Status status =
      client::FromGrpc(client_->PostOutcome({session_id_, session_token_}, frame.frame_id, target,
                                            PackPoints(*points), "", &response),
                       "PostOutcome");
  if (!status.ok()) return status;
  return Answer({frame.stamp, frame.frame, frame.frame_id, target}, response, true);
}

StatusOr<OutcomeAnswer> Bridge::PostAfterCloud(const CloudMessage& after,
                                               const std::optional<RigidTransform>& to_workspace) {
  Frame frame;
  {
    std::lock_guard lock(mutex_);
    Frame* latest = nullptr;
    for (Frame& candidate : frames_) {
      if (candidate.target) latest = &candidate;
    }
    if (latest == nullptr) {
      return FailedPreconditionError("an after-push cloud, but no frame has had a target yet");
    }
    if (latest->outcome_posted) {
      return FailedPreconditionError("an after-push cloud, but the target of the frame stamped " +
                                     StampText(latest->stamp) + " has its outcome already");
    }
    // Claimed now, so that a second after cloud arriving during the call is refused.
    latest->outcome_posted = true;
    frame = *latest;
  }
  StatusOr<OutcomeAnswer> answer = PostAfter(frame, *frame.target, after, to_workspace);
  if (!answer.ok()) {
    std::lock_guard lock(mutex_);
    if (Frame* found = FindFrame(frame.stamp); found != nullptr) found->outcome_posted = false;
  }
  return answer;
}

CloudStep Bridge::OnCloud(const CloudMessage& cloud,
                          const std::optional<RigidTransform>& to_workspace) {
  CloudStep step;
  std::optional<Frame> pushed;
  {
    std::lock_guard lock(mutex_);
    if (awaiting_after_) {
      if (const Frame* found = FindFrame(*awaiting_after_); found != nullptr) pushed = *found;
      awaiting_after_.reset();
    }
  }
  if (pushed) step.after_outcome = PostAfter(*pushed, *pushed->target, cloud, to_workspace);
  step.maps = Map(cloud, to_workspace);
  return step;
}

bool Bridge::TakePush(const FrameMaps& maps) {
  std::lock_guard lock(mutex_);
  if (!config_.push_loop || !maps.target) return false;
  if (config_.max_pushes > 0 && pushes_ >= config_.max_pushes) return false;
  ++pushes_;
  return true;
}

int Bridge::pushes() const {
  std::lock_guard lock(mutex_);
  return pushes_;
}

StatusOr<std::optional<OutcomeAnswer>> Bridge::OnPushReply(const FrameMaps& maps,
                                                           const PushReply& reply) {
  if (reply.result == "failed" || reply.result == "unreachable") {
    return std::optional<OutcomeAnswer>();
  }
  if (reply.result != "done") {
    return InvalidArgumentError("the push service answered result \"" + reply.result +
                                "\", not done, failed or unreachable");
  }
  if (!maps.target) return InvalidArgumentError("a push reply for a frame without a target");
  const Stamp stamp = maps.target->stamp;
  if (reply.label.empty()) {
    std::lock_guard lock(mutex_);
    awaiting_after_ = stamp;
    return std::optional<OutcomeAnswer>();
  }
  if (reply.label != "moved" && reply.label != "still") {
    return InvalidArgumentError("the push service answered label \"" + reply.label +
                                "\", not moved, still or empty");
  }
  StatusOr<OutcomeAnswer> answer =
      PostLabel(stamp, maps.target->supervoxel_id, reply.label == "moved");
  if (!answer.ok()) return answer.status();
  return std::optional<OutcomeAnswer>(std::move(*answer));
}

}  // namespace relmap::ros_bridge
