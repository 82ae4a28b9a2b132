// The loop of one session, stage by stage, each timed.
#include "replication.h"

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include "body_labels.h"
#include "ground_truth.h"
#include "grpc_status.h"
#include "map_snapshots.h"
#include "packed_cloud.h"
#include "seeds.h"
#include "target_choice.h"

namespace relmap::sim {

const char kIterationOrder[] =
    "capture, ComputeMaps, score, choose the target, label (oracle: ground truth; physical: "
    "push, capture, change detector), PostOutcome (learned at once); the map scored at "
    "iteration i has learned the samples of iterations 1..i-1";

namespace {

using Clock = std::chrono::steady_clock;

double MillisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// "replication-<r>-iteration-<i>": the same outcome posted twice (a retry) is learned
// once; unique within a session, which is all the server asks.
std::string RequestId(int replication, int iteration) {
  std::string id = "replication-";
  id += std::to_string(replication);
  id += "-iteration-";
  id += std::to_string(iteration);
  return id;
}

ModelCounts CountsOf(const v1::SessionStats& stats) {
  return {stats.moveable_samples(), stats.non_moveable_samples(), stats.moveable_components(),
          stats.non_moveable_components()};
}

class Replication {
 public:
  Replication(const ExperimentOptions& options, int replication, SimulatedScene& scene,
              client::RelevanceClient& client)
      : options_(options),
        replication_(replication),
        seed_(options.seed + static_cast<std::uint64_t>(replication)),
        scene_(scene),
        client_(client) {}

  ReplicationResult Run(const std::function<void(const IterationRecord&)>& after_iteration) {
    ReplicationResult result;
    result.replication = replication_;
    result.seed = seed_;
    Status status = CreateSession();
    result.session_id = session_.id;
    result.session_token = session_.token;
    for (int i = 1; status.ok() && i <= options_.iterations; ++i) {
      StatusOr<IterationRecord> record = Iterate(i);
      if (!record.ok()) {
        status = record.status();
        break;
      }
      result.iterations.push_back(std::move(*record));
      if (after_iteration) after_iteration(result.iterations.back());
    }
    if (!status.ok()) {
      result.error = "replication " + std::to_string(replication_) + ", iteration " +
                     std::to_string(result.iterations.size() + 1) + ": " + status.message();
    }
    return result;
  }

 private:
  Status CreateSession() {
    v1::SessionConfig config;
    config.set_seed(seed_);
    config.mutable_classifier()->set_variant(options_.variant);
    if (options_.alpha) config.mutable_classifier()->set_alpha(*options_.alpha);
    config.mutable_exploration()->set_novelty(options_.novelty);
    if (options_.random_share)
      config.mutable_exploration()->set_random_share(*options_.random_share);
    if (options_.class_balanced) {
      config.mutable_exploration()->set_class_balanced(*options_.class_balanced);
    }
    if (options_.mode == LabellingMode::kPhysical) {
      v1::ChangeDetectorConfig& change = *config.mutable_change_detector();
      change.set_method(options_.change_method);
      change.set_learn_moved_object(options_.labels != LabelScope::kTarget);
      change.set_ror_min_neighbours(
          options_.change_min_neighbours.value_or(ScaledMinNeighbours(scene_.Capture().width)));
      // The server judges depths by the noise of the camera that took them.
      if (const KinectNoiseModel* noise = scene_.depth_noise()) {
        change.set_noise_sigma_base(noise->axial_constant);
        change.set_noise_sigma_quadratic(noise->axial_quadratic);
        change.set_noise_reference_depth(noise->axial_offset);
        change.set_noise_quantisation(QuantisationCoefficient(*noise));
      }
      // ... and counts as moved what the scene's truth counts (ground_truth.h).
      change.set_min_motion(scene_.motion_threshold());
    }
    return client::FromGrpc(client_.CreateSession(config, &session_), "CreateSession");
  }

  // paper2018 only: §5's 20 neighbours within 1 cm assume a 640×480 Kinect; a camera of the
  // same field of view and `width` columns sees (width / 640)² as many points per area.
  static int ScaledMinNeighbours(std::uint32_t width) {
    const double density = static_cast<double>(width) / 640.0;
    return std::max(3, static_cast<int>(std::lround(20.0 * density * density)));
  }

  StatusOr<IterationRecord> Iterate(int iteration) {
    const Clock::time_point start = Clock::now();
    IterationRecord record;
    record.iteration = iteration;
    IterationTimings& t = record.timings;

    Clock::time_point stage = Clock::now();
    if (options_.mode == LabellingMode::kOracle) {
      scene_.Respawn(IterationSeed(seed_, SeedStream::kRespawn, iteration));
      record.objects_left_out = scene_.last_respawn_failures();
      t.respawn_ms = MillisecondsSince(stage);
      stage = Clock::now();
    }
    CameraFrame frame = Capture();
    const v1::Cloud cloud = PackCloud(frame);
    t.capture_ms = MillisecondsSince(stage);

    stage = Clock::now();
    v1::ComputeMapsResponse maps;
    Status status =
        client::FromGrpc(client_.ComputeMaps(session_, cloud, &maps, client::PointLabels::kInclude,
                                             client::MapsRepeat::kAfterBrokenConnection),
                         "ComputeMaps");
    if (!status.ok()) return status;
    t.maps_ms = MillisecondsSince(stage);
    t.server_maps_ms = maps.timings().total_ms();
    record.supervoxels = static_cast<std::size_t>(maps.supervoxels_size());

    stage = Clock::now();
    StatusOr<std::vector<bool>> object = SupervoxelGroundTruth(
        frame, maps, [this](std::int32_t body) { return scene_.IsMoveable(body); });
    if (!object.ok()) return object.status();
    Score(maps, *object, &record);
    StatusOr<std::optional<int>> target = ChooseTarget(
        maps, options_.sampling, IterationSeed(seed_, SeedStream::kRandomTarget, iteration));
    if (!target.ok()) return target.status();
    t.evaluation_ms = MillisecondsSince(stage);

    if (std::binary_search(options_.snapshots.begin(), options_.snapshots.end(), iteration)) {
      stage = Clock::now();
      status = WriteMapSnapshots(frame, maps, options_.out, replication_, iteration);
      if (!status.ok()) return status;
      t.snapshot_ms = MillisecondsSince(stage);
    }

    if (target->has_value()) {
      status = LabelAndLearn(iteration, frame, maps, **target, *object, &record);
      if (!status.ok()) return status;
    }
    record.mislabelled = mislabelled_;
    record.moved_learned = moved_learned_;
    record.moved_mislabelled = moved_mislabelled_;
    record.model = model_;
    t.iteration_ms = MillisecondsSince(start);
    return record;
  }

  // The scene as it is now. In physical mode after a push, that is what the after-push
  // frame already shows: nothing has moved since.
  CameraFrame Capture() {
    if (after_push_) {
      CameraFrame frame = std::move(*after_push_);
      after_push_.reset();
      return frame;
    }
    return scene_.Capture();
  }

  // Both §6 scores of the relevance map. The metrics are the one implementation of §6
  // (common/metrics.h), shared by the server's tools and the simulator.
  static void Score(const v1::ComputeMapsResponse& maps, const std::vector<bool>& object,
                    IterationRecord* record) {
    Eigen::VectorXd relevance(maps.supervoxels_size());
    for (int i = 0; i < maps.supervoxels_size(); ++i)
      relevance[i] = maps.supervoxels(i).relevance();
    record->thresholded = metrics::ThresholdedSoftScores(relevance, object);
    record->soft = metrics::SoftScores(relevance, object);
  }

  // Pushes (physical) and posts the outcome of supervoxel `index` of `maps` (computed on
  // `frame`), whose supervoxels' ground truth is `moveable`. A push the simulator could not
  // execute (every approach blocked) says nothing about the target: no outcome is posted
  // for it.
  Status LabelAndLearn(int iteration, const CameraFrame& frame, const v1::ComputeMapsResponse& maps,
                       int index, const std::vector<bool>& moveable, IterationRecord* record) {
    const v1::Supervoxel& target = maps.supervoxels(index);
    const bool truth = moveable[static_cast<std::size_t>(index)];
    record->target = target.id();
    const std::string request_id = RequestId(replication_, iteration);
    v1::PostOutcomeResponse response;
    grpc::Status posted;
    if (options_.mode == LabellingMode::kOracle) {
      const Clock::time_point stage = Clock::now();
      std::vector<std::uint32_t> same_object;
      if (options_.labels != LabelScope::kTarget) {
        StatusOr<std::vector<int>> same = SameBody(frame, maps, index);
        if (!same.ok()) return same.status();
        same_object = BodyLabels(options_.labels, truth, maps, index, *same);
      }
      posted = client_.PostOutcome(session_, maps.frame_id(), target.id(),
                                   truth ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE, request_id,
                                   &response, {}, same_object);
      record->timings.outcome_ms = MillisecondsSince(stage);
    } else {
      Clock::time_point stage = Clock::now();
      const Eigen::Vector3f centroid(target.centroid().x(), target.centroid().y(),
                                     target.centroid().z());
      record->push = scene_.Push(centroid, IterationSeed(seed_, SeedStream::kPush, iteration));
      if (!record->push->executed) {
        record->timings.push_ms = MillisecondsSince(stage);
        return OkStatus();
      }
      StatusOr<SupervoxelDisplacement> displacement =
          DisplacementOf(frame, maps, target.id(), *record->push);
      if (!displacement.ok()) return displacement.status();
      record->displacement = *displacement;
      after_push_ = scene_.Capture();
      const v1::Cloud after = PackCloud(*after_push_);
      record->timings.push_ms = MillisecondsSince(stage);
      stage = Clock::now();
      posted =
          client_.PostOutcome(session_, maps.frame_id(), target.id(), after, request_id, &response);
      record->timings.outcome_ms = MillisecondsSince(stage);
    }
    // The push taught nothing; the next iteration asks for new maps.
    if (client::IsFrameGone(posted)) return OkStatus();
    if (Status status = client::FromGrpc(posted, "PostOutcome"); !status.ok()) return status;
    const bool label = response.label() == v1::LABEL_MOVEABLE;
    if (response.has_evidence()) record->change = response.evidence();
    record->label = label;
    record->truth = truth;
    if (label != truth) ++mislabelled_;
    // Physical mode names what the detector saw move; oracle mode's are the true body.
    moved_learned_ += response.moved_learned() + response.object_learned();
    for (const std::uint32_t id : response.evidence().moved_supervoxels()) {
      moved_mislabelled_ += !moveable[id];
    }
    model_ = CountsOf(response.stats());
    return OkStatus();
  }

  // The indices of the other supervoxels of `maps` that show the body supervoxel `index`
  // shows (ground_truth.h): what a push of it moves with it. None when it shows no
  // single body.
  static StatusOr<std::vector<int>> SameBody(const CameraFrame& frame,
                                             const v1::ComputeMapsResponse& maps, int index) {
    StatusOr<std::vector<std::int32_t>> bodies = SupervoxelBodies(frame, maps);
    if (!bodies.ok()) return bodies.status();
    const std::int32_t body = (*bodies)[static_cast<std::size_t>(index)];
    std::vector<int> same;
    if (body == kNoBody) return same;
    for (int j = 0; j < maps.supervoxels_size(); ++j) {
      if (j != index && (*bodies)[static_cast<std::size_t>(j)] == body) same.push_back(j);
    }
    return same;
  }

  const ExperimentOptions& options_;
  const int replication_;
  const std::uint64_t seed_;
  SimulatedScene& scene_;
  client::RelevanceClient& client_;
  client::SessionHandle session_;
  std::optional<CameraFrame> after_push_;
  std::uint64_t mislabelled_ = 0;
  std::uint64_t moved_learned_ = 0;
  std::uint64_t moved_mislabelled_ = 0;
  ModelCounts model_;
};

}  // namespace

ReplicationResult RunReplication(
    const ExperimentOptions& options, int replication, SimulatedScene& scene,
    client::RelevanceClient& client,
    const std::function<void(const IterationRecord&)>& after_iteration) {
  return Replication(options, replication, scene, client).Run(after_iteration);
}

}  // namespace relmap::sim
