// RunReplication does the pushing; this file only sets it up and reads the session back.
#include "physical_dataset.h"

#include <memory>

#include "experiment_options.h"
#include "grpc_status.h"
#include "progress_bar.h"
#include "replication.h"

namespace relmap::sim {

StatusOr<std::vector<LearnedSample>> CollectLearnedSamples(const DatasetOptions& options,
                                                           SimulatedScene& scene,
                                                           client::RelevanceClient& client,
                                                           std::FILE* progress) {
  ExperimentOptions run;
  run.scene = options.scene;
  run.mode = LabellingMode::kPhysical;
  run.iterations = options.frames;
  run.seed = options.seed;
  run.resolution = options.resolution;
  run.snapshots = {};  // nothing is written but the dataset
  std::unique_ptr<client::ProgressBar> bar;
  if (progress != nullptr) {
    bar = std::make_unique<client::ProgressBar>(
        "pushes", static_cast<std::uint64_t>(options.frames), progress);
  }
  const ReplicationResult result =
      RunReplication(run, 0, scene, client, [&bar](const IterationRecord& record) {
        if (bar) bar->Update(static_cast<std::uint64_t>(record.iteration));
      });
  if (bar) bar->Finish();
  const client::SessionHandle session{result.session_id, result.session_token};
  v1::ExportSessionResponse exported;
  Status status = result.error.empty()
                      ? client::FromGrpc(client.ExportSession(session, &exported), "ExportSession")
                      : InternalError(result.error);
  // On a shared server the session would stay until it expires.
  if (!session.id.empty()) client.DeleteSession(session);
  if (!status.ok()) return status;
  return PairLearnedSamples(result.iterations, exported.state());
}

}  // namespace relmap::sim
