// One session: its settings, classifier, RNG, frame cache and the answers to
// requests already served. Every public method is serialised on the session's
// own mutex; different sessions run in parallel.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cmm/collaborative_mixture_models.h"
#include "common/random.h"
#include "common/status.h"
#include "exploration/frame_maps.h"
#include "perception/change_before.h"
#include "perception/change_detector.h"
#include "perception/frame.h"
#include "session/session_settings.h"
#include "session/store/session_store.h"

namespace relmap::session {

struct SessionStats {
  std::uint64_t samples[2] = {0, 0};  // per label: 0 non-moveable, 1 moveable
  std::uint32_t components[2] = {0, 0};
  std::uint64_t frames = 0;
  std::int64_t created_unix_ms = 0;
  std::int64_t last_used_unix_ms = 0;
};

// What an outcome taught the session.
struct Outcome {
  SessionStats stats;
  int label = -1;  // 0 or 1 as learned
  // Set when the label came from the change detector.
  std::optional<perception::ChangeEvidence> evidence;
  // Of the supervoxels posted as moved with the target, those learned (the usable ones).
  std::uint32_t moved_learned = 0;
  // Of those posted as on the target's object, those learned.
  std::uint32_t object_learned = 0;
};

// Other supervoxels of the frame an outcome labels beside its target (docs/method.md
// §4.5): each one the frame has, not the target, none repeated within or across the lists.
struct Alongside {
  std::span<const std::uint32_t> moved;        // moved with the target: learned as moveable
  std::span<const std::uint32_t> same_object;  // the rest of its rigid object: its label
};

// Answers a session keeps for retried requests.
inline constexpr std::size_t kRememberedAnswers = 10000;

// What ExportSession carries besides the settings.
struct SessionState {
  Eigen::MatrixXd features;  // one sample per row, in learning order
  std::vector<int> labels;
  Random::State target_random{};
  std::uint64_t interactions = 0;
};

// A frame with its maps, as ComputeMaps returns it.
struct MappedFrame {
  std::uint64_t frame_id = 0;
  std::shared_ptr<const perception::Frame> frame;
  exploration::FrameMaps maps;
  double maps_ms = 0.0;
};

// What the frame cache keeps of a frame for its outcomes: the features to learn and, for an
// outcome with the cloud after the push, what the change detector reads (the maps, normals
// and the decoded cloud go: ~1 MB instead of ~12 for a 640x480 frame).
struct CachedFrame {
  std::uint64_t frame_id = 0;
  Eigen::MatrixXd features;  // row i: supervoxel i
  perception::ChangeBefore change_before;

  std::size_t bytes() const;
};

class Session {
 public:
  // A new, empty session. Invalid settings → INVALID_ARGUMENT. With a `store`,
  // every sample is committed there before the session learns it.
  static StatusOr<std::unique_ptr<Session>> Create(std::string id, std::string token_hash,
                                                   SessionSettings settings,
                                                   std::int64_t now_unix_ms,
                                                   SessionStore* store = nullptr);

  // Relearns stored samples in sequence order (after a restart): the same
  // samples in the same order rebuild the same model, bit for bit. Samples the
  // model has already learned (from a snapshot) are skipped.
  Status Replay(const std::vector<StoredSample>& samples);
  // Starts an empty session from a stored model snapshot (bit for bit).
  Status RestoreModel(const cmm::CmmSnapshot& snapshot);
  // After a restart or a reload, from the stored counters: frame ids continue after
  // the `frames` already issued (an outcome for a frame of the previous life is never
  // matched with a new frame of the same id), and the target-draw stream skips the
  // `interactions` draws already made, so that the session draws as if it had never
  // stopped (each draw takes one 64-bit word of the stream).
  void RestoreCounters(std::uint64_t frames, std::uint64_t interactions);
  // After a restart or a reload: the last call as the store recorded it.
  void RestoreLastUsed(std::int64_t unix_ms);
  // The server's snapshot cadence and frame cache for this session.
  void set_policy(const SessionPolicy& policy);

  const std::string& id() const { return id_; }
  const std::string& token_hash() const { return token_hash_; }
  const SessionSettings& settings() const { return settings_; }

  // Supervoxels, features and maps of a decoded cloud; the frame joins the cache
  // and the target is drawn with the session's RNG. FAILED_PRECONDITION for a
  // session fed with features of another dimension.
  StatusOr<MappedFrame> ComputeMaps(perception::Cloud cloud, std::int64_t now_unix_ms);

  // Learns that pushing `supervoxel_id` of frame `frame_id` gave `label` (0 or 1).
  // An unknown or evicted frame → FAILED_PRECONDITION; a supervoxel the frame does
  // not have, or one with non-finite features → INVALID_ARGUMENT. A request id
  // seen before returns the first answer and learns nothing.
  // `alongside`: other supervoxels of the frame, each learned after the target
  // (docs/method.md §4.5) unless its features are not finite; INVALID_ARGUMENT, and
  // nothing learned, for one the frame does not have, a repeat or the target itself.
  StatusOr<Outcome> PostOutcome(std::uint64_t frame_id, std::uint32_t supervoxel_id, int label,
                                const std::string& request_id, std::int64_t now_unix_ms,
                                const Alongside& alongside = {});

  // The same, with the label decided by the change detector (docs/method.md §5) from
  // the frame's cloud and `after`, the cloud after the push.
  StatusOr<Outcome> PostOutcomeFromCloud(std::uint64_t frame_id, std::uint32_t supervoxel_id,
                                         const perception::Cloud& after,
                                         const std::string& request_id, std::int64_t now_unix_ms,
                                         const Alongside& alongside = {});

  // Relevance and choice maps of raw feature vectors (one per row); no target is
  // drawn and nothing is learned.
  StatusOr<exploration::FrameMaps> ClassifyFeatures(const Eigen::MatrixXd& features,
                                                    std::int64_t now_unix_ms);

  // Learns labelled feature vectors in order, all or none: every row is checked
  // before the first is learned. Idempotent on `request_id` as PostOutcome.
  StatusOr<SessionStats> AddSamples(const Eigen::MatrixXd& features, const std::vector<int>& labels,
                                    const std::string& request_id, std::int64_t now_unix_ms);

  SessionStats Stats() const;
  // Records in the store what a listing shows of the session while it is not in
  // memory (ModelSummary: its components and last call). Done after every call that
  // learns; the registry calls it when it unloads the session. Best effort: a summary
  // that was not recorded only makes a listing load the session.
  void RecordSummary();

  // The dataset and target-draw state, for ExportSession.
  SessionState ExportState() const;
  // Learns an exported dataset (persisted like AddSamples) and takes over its
  // target-draw state; for a new, empty session only (else FAILED_PRECONDITION).
  StatusOr<SessionStats> ImportState(const SessionState& state, std::int64_t now_unix_ms);

 private:
  Session(std::string id, std::string token_hash, SessionSettings settings,
          cmm::CollaborativeMixtureModels model, std::int64_t now_unix_ms, SessionStore* store);
  SessionStats StatsLocked() const;
  void RecordSummaryLocked();
  // The cached frame `frame_id`, after checking that it has a learnable
  // supervoxel `supervoxel_id`.
  StatusOr<std::shared_ptr<const CachedFrame>> FrameForOutcomeLocked(
      std::uint64_t frame_id, std::uint32_t supervoxel_id) const;
  // Persists and learns the supervoxel's features with `label`, then each of
  // `alongside.moved` as moveable and of `alongside.same_object` with `label`, and
  // remembers the answer under `request_id`.
  StatusOr<Outcome> LearnOutcomeLocked(const CachedFrame& frame, std::uint32_t supervoxel_id,
                                       int label, const Alongside& alongside,
                                       const std::string& request_id,
                                       std::optional<perception::ChangeEvidence> evidence,
                                       std::int64_t now_unix_ms);
  Status CheckFeatures(const Eigen::MatrixXd& features) const;
  // Commits a sample to the store (if any) and learns it, unless the store had
  // it already under this request id (a retry after a restart).
  Status PersistAndLearn(const std::string& request_id, const Eigen::VectorXd& x, int label);

  const std::string id_;
  const std::string token_hash_;
  const SessionSettings settings_;
  SessionStore* const store_;  // null: in memory only

  mutable std::mutex mutex_;
  cmm::CollaborativeMixtureModels model_;
  Random random_;  // target draws; the classifier has its own stream
  std::uint64_t next_frame_id_ = 1;
  std::uint64_t frames_ = 0;
  std::uint64_t interactions_ = 0;
  SessionPolicy policy_;
  // Time spent in model updates since the last snapshot (SessionPolicy).
  std::chrono::steady_clock::duration learning_since_snapshot_{};
  std::deque<std::shared_ptr<const CachedFrame>> frames_cache_;
  // Remembers the answer under `request_id`, forgetting the oldest beyond
  // kRememberedAnswers (with a store, older retries are still not learned twice:
  // the store deduplicates them).
  void RememberLocked(const std::string& request_id, const Outcome& outcome);
  // The answer given before under `request_id`, or null (always for an empty id).
  const Outcome* AnsweredLocked(const std::string& request_id) const;

  std::map<std::string, Outcome> answered_;  // request id → the answer given
  std::deque<std::string> answered_order_;   // oldest first
  std::int64_t created_unix_ms_;
  std::int64_t last_used_unix_ms_;
};

}  // namespace relmap::session
