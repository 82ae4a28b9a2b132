// A session's calls: maps of a cloud, outcomes, raw features.
#include "session/session.h"

#include <algorithm>
#include <chrono>
#include <span>
#include <string>
#include <utility>

#include "session/credentials.h"

namespace relmap::session {
namespace {

// The target draws take their own stream, derived from the session seed, so
// that drawing targets never shifts the classifier's re-check stream.
constexpr std::uint64_t kTargetStream = 0x5eed5eed5eed5eedULL;

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

StatusOr<std::unique_ptr<Session>> Session::Create(std::string id, std::string token_hash,
                                                   SessionSettings settings,
                                                   std::int64_t now_unix_ms, SessionStore* store) {
  if (Status status = Validate(settings); !status.ok()) return status;
  auto model =
      cmm::CollaborativeMixtureModels::Create(settings.classifier, settings.feature_dimension);
  if (!model.ok()) return model.status();
  return std::unique_ptr<Session>(new Session(std::move(id), std::move(token_hash), settings,
                                              std::move(model).value(), now_unix_ms, store));
}

Session::Session(std::string id, std::string token_hash, SessionSettings settings,
                 cmm::CollaborativeMixtureModels model, std::int64_t now_unix_ms,
                 SessionStore* store)
    : id_(std::move(id)),
      token_hash_(std::move(token_hash)),
      settings_(settings),
      store_(store),
      model_(std::move(model)),
      random_(settings_.classifier.seed ^ kTargetStream),
      created_unix_ms_(now_unix_ms),
      last_used_unix_ms_(now_unix_ms) {}

StatusOr<MappedFrame> Session::ComputeMaps(perception::Cloud cloud, std::int64_t now_unix_ms) {
  if (settings_.feature_dimension != kCloudFeatureDimension) {
    return FailedPreconditionError("session " + id_ + " learns " +
                                   std::to_string(settings_.feature_dimension) +
                                   "-d features; clouds give 48-d ones");
  }
  // Segmentation and features need no session state: they run before the lock,
  // so a session's next cloud can be prepared while the previous one is mapped.
  auto frame = perception::BuildFrame(std::move(cloud), settings_.perception);
  if (!frame.ok()) return frame.status();
  auto shared = std::make_shared<const perception::Frame>(std::move(frame).value());
  if (shared->size() == 0) {
    return InvalidArgumentError("the cloud gave no supervoxel (too few points in the workspace)");
  }
  // Packing takes a few milliseconds: before the lock too.
  auto cached = std::make_shared<CachedFrame>(
      CachedFrame{0, shared->features.values,
                  perception::ChangeBefore::Of(*shared, settings_.perception.change)});

  std::lock_guard lock(mutex_);
  const auto start = std::chrono::steady_clock::now();
  MappedFrame mapped;
  mapped.frame_id = next_frame_id_++;
  mapped.frame = std::move(shared);
  mapped.maps =
      exploration::ComputeFrameMaps(model_, mapped.frame->features.values, settings_.exploration,
                                    static_cast<int>(interactions_), &random_);
  mapped.maps_ms = MillisecondsSince(start);
  const bool drew = mapped.maps.target >= 0;
  if (store_ != nullptr) {
    // Committed before the frame is answered: a restart continues its ids and draws.
    if (Status stored = store_->IncrementCounters(id_, {1, drew ? 1 : 0}); !stored.ok()) {
      return stored;
    }
  }
  if (drew) ++interactions_;
  ++frames_;
  last_used_unix_ms_ = now_unix_ms;
  cached->frame_id = mapped.frame_id;
  frames_cache_.push_back(std::move(cached));
  if (frames_cache_.size() > policy_.frame_cache) frames_cache_.pop_front();
  return mapped;
}

std::size_t CachedFrame::bytes() const {
  return sizeof(CachedFrame) + static_cast<std::size_t>(features.size()) * sizeof(double) +
         change_before.bytes();
}

StatusOr<std::shared_ptr<const CachedFrame>> Session::FrameForOutcomeLocked(
    std::uint64_t frame_id, std::uint32_t supervoxel_id) const {
  std::shared_ptr<const CachedFrame> cached;
  for (const auto& f : frames_cache_) {
    if (f->frame_id == frame_id) cached = f;
  }
  if (cached == nullptr) {
    return FailedPreconditionError("frame " + std::to_string(frame_id) + " of session " + id_ +
                                   " is unknown or no longer cached (the cache keeps the last " +
                                   std::to_string(policy_.frame_cache) + " frames)")
        .WithReason(ErrorReason::kFrameGone,
                    {{"sessionId", id_}, {"frameId", std::to_string(frame_id)}});
  }
  const Eigen::MatrixXd& features = cached->features;
  if (supervoxel_id >= features.rows()) {
    return InvalidArgumentError("frame " + std::to_string(frame_id) + " has " +
                                std::to_string(features.rows()) + " supervoxels, no id " +
                                std::to_string(supervoxel_id));
  }
  if (!features.row(static_cast<Eigen::Index>(supervoxel_id)).allFinite()) {
    return InvalidArgumentError("supervoxel " + std::to_string(supervoxel_id) + " of frame " +
                                std::to_string(frame_id) +
                                " has non-finite features and cannot be learned");
  }
  return cached;
}

namespace {

// The supervoxels a client labels beside the target: each one the frame has, not the
// target and not repeated, within a list or across the two.
Status CheckAlongside(const Eigen::MatrixXd& features, std::uint64_t frame_id, std::uint32_t target,
                      const Alongside& alongside) {
  std::vector<bool> seen(static_cast<std::size_t>(features.rows()), false);
  seen[target] = true;
  for (const auto& [list, name] :
       {std::pair{alongside.moved, "moved"}, std::pair{alongside.same_object, "same-object"}}) {
    for (const std::uint32_t id : list) {
      const std::string which = std::string(name) + " supervoxel " + std::to_string(id) +
                                " of frame " + std::to_string(frame_id);
      if (id >= features.rows()) {
        return InvalidArgumentError(which + ": the frame has " + std::to_string(features.rows()) +
                                    " supervoxels");
      }
      if (seen[id]) return InvalidArgumentError(which + " is the target or a repeat");
      seen[id] = true;
    }
  }
  return OkStatus();
}

// The client's moved supervoxels, then those the change detector saw move that the client
// did not name in either list (the detector never names the target).
std::vector<std::uint32_t> WithDetected(const Alongside& from_client,
                                        const std::vector<std::uint32_t>& detected) {
  std::vector<std::uint32_t> moved(from_client.moved.begin(), from_client.moved.end());
  const auto named = [&](std::uint32_t id) {
    return std::find(moved.begin(), moved.end(), id) != moved.end() ||
           std::find(from_client.same_object.begin(), from_client.same_object.end(), id) !=
               from_client.same_object.end();
  };
  for (const std::uint32_t id : detected) {
    if (!named(id)) moved.push_back(id);
  }
  return moved;
}

}  // namespace

StatusOr<Outcome> Session::LearnOutcomeLocked(const CachedFrame& frame, std::uint32_t supervoxel_id,
                                              int label, const Alongside& alongside,
                                              const std::string& request_id,
                                              std::optional<perception::ChangeEvidence> evidence,
                                              std::int64_t now_unix_ms) {
  const std::string key = request_id.empty() ? "auto-" + RandomHex(12) : request_id;
  const auto row = static_cast<Eigen::Index>(supervoxel_id);
  if (Status status = PersistAndLearn(key, frame.features.row(row).transpose(), label);
      !status.ok()) {
    return status;
  }
  // One store key per sample, as AddSamples: a retry skips what was committed already.
  // Unusable rows (non-finite features) are skipped: nothing can be learned from them.
  const auto learn_each = [&](std::span<const std::uint32_t> ids, const char* part,
                              int as) -> StatusOr<std::uint32_t> {
    std::uint32_t learned = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const auto other = static_cast<Eigen::Index>(ids[i]);
      if (!frame.features.row(other).allFinite()) continue;
      if (Status status = PersistAndLearn(key + part + std::to_string(i),
                                          frame.features.row(other).transpose(), as);
          !status.ok()) {
        return status;
      }
      ++learned;
    }
    return learned;
  };
  StatusOr<std::uint32_t> moved_learned = learn_each(alongside.moved, "/moved/", 1);
  if (!moved_learned.ok()) return moved_learned.status();
  StatusOr<std::uint32_t> object_learned = learn_each(alongside.same_object, "/object/", label);
  if (!object_learned.ok()) return object_learned.status();
  last_used_unix_ms_ = now_unix_ms;
  RecordSummaryLocked();
  Outcome outcome{StatsLocked(), label, std::move(evidence), *moved_learned, *object_learned};
  if (!request_id.empty()) RememberLocked(request_id, outcome);
  return outcome;
}

StatusOr<Outcome> Session::PostOutcome(std::uint64_t frame_id, std::uint32_t supervoxel_id,
                                       int label, const std::string& request_id,
                                       std::int64_t now_unix_ms, const Alongside& alongside) {
  std::lock_guard lock(mutex_);
  if (const Outcome* answered = AnsweredLocked(request_id)) return *answered;
  if (label != 0 && label != 1) return InvalidArgumentError("label must be 0 or 1");
  auto frame = FrameForOutcomeLocked(frame_id, supervoxel_id);
  if (!frame.ok()) return frame.status();
  if (Status status = CheckAlongside((*frame)->features, frame_id, supervoxel_id, alongside);
      !status.ok()) {
    return status;
  }
  return LearnOutcomeLocked(**frame, supervoxel_id, label, alongside, request_id, std::nullopt,
                            now_unix_ms);
}

StatusOr<Outcome> Session::PostOutcomeFromCloud(std::uint64_t frame_id, std::uint32_t supervoxel_id,
                                                const perception::Cloud& after,
                                                const std::string& request_id,
                                                std::int64_t now_unix_ms,
                                                const Alongside& alongside) {
  std::shared_ptr<const CachedFrame> frame;
  {
    std::lock_guard lock(mutex_);
    if (const Outcome* answered = AnsweredLocked(request_id)) return *answered;
    auto found = FrameForOutcomeLocked(frame_id, supervoxel_id);
    if (!found.ok()) return found.status();
    frame = std::move(found).value();
  }
  if (Status status = CheckAlongside(frame->features, frame_id, supervoxel_id, alongside);
      !status.ok()) {
    return status;
  }
  // Unpacking and the detector (tens of milliseconds) run without the lock; the frame
  // is shared, so an eviction meanwhile does not pull it away.
  auto before = frame->change_before.Expand(supervoxel_id);
  if (!before.ok()) return before.status();
  auto evidence = perception::DetectChange(before->before, after, before->target,
                                           before->ObjectPointers(), settings_.perception.change);
  if (!evidence.ok()) return evidence.status();
  const int label = evidence->moved ? 1 : 0;
  // What the camera saw move went with the target: learned as the client's list is (§4.5).
  const std::vector<std::uint32_t> moved =
      settings_.perception.change.learn_moved_object
          ? WithDetected(alongside, evidence->moved_supervoxels)
          : std::vector<std::uint32_t>(alongside.moved.begin(), alongside.moved.end());

  std::lock_guard lock(mutex_);
  if (const Outcome* answered = AnsweredLocked(request_id)) return *answered;
  return LearnOutcomeLocked(*frame, supervoxel_id, label, {moved, alongside.same_object},
                            request_id, std::move(evidence).value(), now_unix_ms);
}

Status Session::CheckFeatures(const Eigen::MatrixXd& features) const {
  if (features.cols() != settings_.feature_dimension) {
    return InvalidArgumentError("feature vectors have " + std::to_string(features.cols()) +
                                " values, session " + id_ + " expects " +
                                std::to_string(settings_.feature_dimension));
  }
  for (Eigen::Index i = 0; i < features.rows(); ++i) {
    if (!features.row(i).allFinite()) {
      return InvalidArgumentError("feature vector " + std::to_string(i) +
                                  " has a non-finite value");
    }
  }
  return OkStatus();
}

StatusOr<exploration::FrameMaps> Session::ClassifyFeatures(const Eigen::MatrixXd& features,
                                                           std::int64_t now_unix_ms) {
  if (Status status = CheckFeatures(features); !status.ok()) return status;
  std::lock_guard lock(mutex_);
  last_used_unix_ms_ = now_unix_ms;
  return exploration::ComputeFrameMaps(model_, features, settings_.exploration,
                                       static_cast<int>(interactions_), nullptr);
}

StatusOr<SessionStats> Session::AddSamples(const Eigen::MatrixXd& features,
                                           const std::vector<int>& labels,
                                           const std::string& request_id,
                                           std::int64_t now_unix_ms) {
  if (Status status = CheckFeatures(features); !status.ok()) return status;
  if (labels.size() != static_cast<std::size_t>(features.rows())) {
    return InvalidArgumentError("every sample needs a label");
  }
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != 0 && labels[i] != 1) {
      return InvalidArgumentError("sample " + std::to_string(i) + " has no valid label");
    }
  }
  std::lock_guard lock(mutex_);
  if (const Outcome* answered = AnsweredLocked(request_id)) return answered->stats;
  // One store key per sample: a retried batch skips what was committed already.
  const std::string prefix = request_id.empty() ? "auto-" + RandomHex(12) : request_id;
  for (Eigen::Index i = 0; i < features.rows(); ++i) {
    if (Status status =
            PersistAndLearn(prefix + "/" + std::to_string(i), features.row(i).transpose(),
                            labels[static_cast<std::size_t>(i)]);
        !status.ok()) {
      return status;
    }
  }
  last_used_unix_ms_ = now_unix_ms;
  RecordSummaryLocked();
  Outcome outcome{StatsLocked(), -1, std::nullopt};
  if (!request_id.empty()) RememberLocked(request_id, outcome);
  return outcome.stats;
}

Status Session::PersistAndLearn(const std::string& request_id, const Eigen::VectorXd& x,
                                int label) {
  if (store_ != nullptr) {
    // Acknowledged only once committed: the store comes first, then the model.
    const auto sequence =
        store_->AppendSample(id_, request_id, std::span<const double>(x.data(), x.size()), label);
    if (!sequence.ok()) return sequence.status();
    const std::int64_t learned = model_.dataset().size();
    if (*sequence < learned) return OkStatus();  // stored and learned before a restart
    if (*sequence > learned) {
      return DataLossError("session " + id_ + ": the store holds " + std::to_string(*sequence) +
                           " samples, the model " + std::to_string(learned));
    }
  }
  const auto start = std::chrono::steady_clock::now();
  auto added = model_.Add(x, label);
  if (!added.ok()) return added.status();
  learning_since_snapshot_ += std::chrono::steady_clock::now() - start;
  const auto learned = static_cast<std::size_t>(model_.dataset().size());
  const bool every = policy_.snapshot_every > 0 && learned % policy_.snapshot_every == 0;
  const bool after_learning = policy_.snapshot_after_learning.count() > 0 &&
                              learning_since_snapshot_ >= policy_.snapshot_after_learning;
  if (store_ != nullptr && (every || after_learning)) {
    // A failed snapshot loses nothing (the samples are the record): log-worthy,
    // not an error of this call.
    (void)store_->SaveSnapshot(id_, model_.Snapshot(), static_cast<std::int64_t>(learned));
    learning_since_snapshot_ = {};
  }
  return OkStatus();
}

void Session::set_policy(const SessionPolicy& policy) {
  std::lock_guard lock(mutex_);
  policy_ = policy;
  while (frames_cache_.size() > policy_.frame_cache) frames_cache_.pop_front();
}

Status Session::RestoreModel(const cmm::CmmSnapshot& snapshot) {
  std::lock_guard lock(mutex_);
  if (model_.dataset().size() != 0) {
    return FailedPreconditionError("session " + id_ + " has learned samples already");
  }
  auto restored = cmm::CollaborativeMixtureModels::Restore(snapshot);
  if (!restored.ok()) return restored.status();
  model_ = std::move(restored).value();
  return OkStatus();
}

Status Session::Replay(const std::vector<StoredSample>& samples) {
  std::lock_guard lock(mutex_);
  for (const StoredSample& sample : samples) {
    if (sample.sequence < model_.dataset().size()) continue;  // in the restored snapshot
    const Eigen::Map<const Eigen::VectorXd> x(sample.features.data(),
                                              static_cast<Eigen::Index>(sample.features.size()));
    if (auto added = model_.Add(x, sample.label); !added.ok()) {
      return DataLossError("session " + id_ + ": stored sample " + std::to_string(sample.sequence) +
                           " cannot be relearned: " + added.status().message());
    }
  }
  // A retried PostOutcome whose first answer was lost in the restart is answered
  // again, not refused for want of its (unpersisted) frame. AddSamples batches are
  // stored per sample ("<id>/<i>") and deduplicated by the store instead.
  const Outcome answer{StatsLocked(), 0, std::nullopt};
  const std::size_t first =
      samples.size() > kRememberedAnswers ? samples.size() - kRememberedAnswers : 0;
  for (std::size_t i = first; i < samples.size(); ++i) {
    Outcome outcome = answer;
    outcome.label = samples[i].label;
    RememberLocked(samples[i].request_id, outcome);
  }
  return OkStatus();
}

void Session::RestoreCounters(std::uint64_t frames, std::uint64_t interactions) {
  std::lock_guard lock(mutex_);
  frames_ = frames;
  next_frame_id_ = frames + 1;
  interactions_ = interactions;
  for (std::uint64_t i = 0; i < interactions; ++i) (void)random_.NextBits();
}

void Session::RestoreLastUsed(std::int64_t unix_ms) {
  std::lock_guard lock(mutex_);
  last_used_unix_ms_ = unix_ms;
}

const Outcome* Session::AnsweredLocked(const std::string& request_id) const {
  if (request_id.empty()) return nullptr;  // no id: never a retry
  const auto it = answered_.find(request_id);
  return it == answered_.end() ? nullptr : &it->second;
}

void Session::RememberLocked(const std::string& request_id, const Outcome& outcome) {
  if (answered_.emplace(request_id, outcome).second) answered_order_.push_back(request_id);
  while (answered_order_.size() > kRememberedAnswers) {
    answered_.erase(answered_order_.front());
    answered_order_.pop_front();
  }
}

SessionState Session::ExportState() const {
  std::lock_guard lock(mutex_);
  SessionState state;
  state.features = model_.dataset().features();
  state.labels.assign(model_.dataset().labels().begin(), model_.dataset().labels().end());
  state.target_random = random_.state();
  state.interactions = interactions_;
  return state;
}

StatusOr<SessionStats> Session::ImportState(const SessionState& state, std::int64_t now_unix_ms) {
  {
    std::lock_guard lock(mutex_);
    if (model_.dataset().size() != 0) {
      return FailedPreconditionError("session " + id_ +
                                     " has samples already; import into a new one");
    }
  }
  StatusOr<SessionStats> stats = Stats();
  if (state.features.rows() > 0) {
    stats = AddSamples(state.features, state.labels, "import", now_unix_ms);
    if (!stats.ok()) return stats.status();
  }
  std::lock_guard lock(mutex_);
  // The store keeps the draw count, from which a restart rebuilds the stream: exact for
  // a state exported by relmap (its stream is the seed's, advanced one word per draw).
  if (store_ != nullptr && state.interactions > 0) {
    const SessionCounters imported{0, static_cast<std::int64_t>(state.interactions)};
    if (Status stored = store_->IncrementCounters(id_, imported); !stored.ok()) return stored;
  }
  random_ = Random::FromState(state.target_random);
  interactions_ = state.interactions;
  return StatsLocked();
}

SessionStats Session::Stats() const {
  std::lock_guard lock(mutex_);
  return StatsLocked();
}

void Session::RecordSummary() {
  std::lock_guard lock(mutex_);
  RecordSummaryLocked();
}

void Session::RecordSummaryLocked() {
  if (store_ == nullptr) return;
  ModelSummary summary;
  summary.sample_count = model_.dataset().size();
  for (int label = 0; label < 2; ++label) summary.components[label] = model_.component_count(label);
  summary.last_used = Timestamp(std::chrono::milliseconds(last_used_unix_ms_));
  // A failure loses nothing (the samples are the record): a listing then loads the
  // session instead of reading its summary.
  (void)store_->RecordModelSummary(id_, summary);
}

SessionStats Session::StatsLocked() const {
  SessionStats stats;
  for (int label = 0; label < 2; ++label) {
    stats.samples[label] = static_cast<std::uint64_t>(model_.sample_count(label));
    stats.components[label] = static_cast<std::uint32_t>(model_.component_count(label));
  }
  stats.frames = frames_;
  stats.created_unix_ms = created_unix_ms_;
  stats.last_used_unix_ms = last_used_unix_ms_;
  return stats;
}

}  // namespace relmap::session
