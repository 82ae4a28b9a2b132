// Replaying a run directory into a new session.
#include "replay.h"

#include <cstdint>
#include <vector>

#include "exploration_loop.h"
#include "grpc_status.h"
#include "map_accuracy.h"
#include "robot_messages.pb.h"
#include "run_record.h"

namespace relmap::robot {

StatusOr<ReplayResult> ReplayRun(const std::string& run_dir, client::RelevanceClient& client) {
  RunSession run;
  if (Status s = ReadJson(run_dir + "/session.json", &run); !s.ok()) return s;
  ReplayResult result;
  if (Status s =
          client::FromGrpc(client.CreateSession(run.config(), &result.session), "CreateSession");
      !s.ok()) {
    return s;
  }
  const std::string replay_id = "replay-" + client::RandomRequestId();
  for (int iteration : RecordedIterations(run_dir)) {
    const std::string directory = IterationDirectory(run_dir, iteration);
    v1::PostOutcomeResponse label;
    if (!ReadJson(directory + "/label.json", &label).ok()) continue;  // nothing was learned
    DriverRequest target;
    v1::ComputeMapsResponse recorded_maps;
    if (Status s = ReadJson(directory + "/target.json", &target); !s.ok()) return s;
    if (Status s = ReadJson(directory + "/maps.json", &recorded_maps); !s.ok()) return s;
    StatusOr<v1::Cloud> before = ReadCloud(directory, "before");
    if (!before.ok()) return before.status();

    v1::ComputeMapsResponse maps;
    if (Status s = client::FromGrpc(
            client.ComputeMaps(result.session, *before, &maps, client::PointLabels::kOmit),
            "ComputeMaps");
        !s.ok()) {
      return s;
    }
    if (maps.supervoxels_size() != recorded_maps.supervoxels_size()) {
      return FailedPreconditionError(
          directory + ": the replayed cloud has " + std::to_string(maps.supervoxels_size()) +
          " supervoxels, the recorded maps " + std::to_string(recorded_maps.supervoxels_size()));
    }
    ReplayedIteration replayed;
    replayed.iteration = iteration;
    replayed.supervoxel = target.supervoxel();
    replayed.label = label.label();
    IterationTruth truth;
    if (ReadJson(directory + "/truth.json", &truth).ok()) {
      replayed.accuracy =
          MapAccuracy(maps, std::vector<bool>(truth.moveable().begin(), truth.moveable().end()));
    }
    // The parts the change detector saw move with the target were learned with it when
    // the session's learn_moved_object was on (moved_learned > 0): the replay names them,
    // so that it learns what the run learned.
    std::vector<std::uint32_t> moved;
    if (label.moved_learned() > 0) {
      moved.assign(label.evidence().moved_supervoxels().begin(),
                   label.evidence().moved_supervoxels().end());
    }
    v1::PostOutcomeResponse posted;
    if (Status s = client::FromGrpc(
            client.PostOutcome(result.session, maps.frame_id(), target.supervoxel(), label.label(),
                               OutcomeRequestId(replay_id, iteration), &posted, moved),
            "PostOutcome");
        !s.ok()) {
      return s;
    }
    result.iterations.push_back(replayed);
  }
  return result;
}

}  // namespace relmap::robot
