// Re-spawn, capture, ComputeMaps with features, ground truth: replication.cpp's oracle
// iteration without the scoring, the target or the outcome.
#include "dataset_frame.h"

#include <algorithm>
#include <cmath>

#include "ground_truth.h"
#include "grpc_status.h"
#include "packed_cloud.h"
#include "seeds.h"

namespace relmap::sim {

StatusOr<LabelledFrame> LabelFrame(SimulatedScene& scene, client::RelevanceClient& client,
                                   const client::SessionHandle& session, std::uint64_t seed,
                                   int frame) {
  scene.Respawn(IterationSeed(seed, SeedStream::kRespawn, frame));
  const CameraFrame captured = scene.Capture();
  v1::ComputeMapsResponse maps;
  if (Status status = client::FromGrpc(
          client.ComputeMaps(session, PackCloud(captured), &maps, client::PointLabels::kInclude,
                             client::MapsRepeat::kAfterBrokenConnection,
                             client::SupervoxelFeatures::kInclude),
          "ComputeMaps");
      !status.ok()) {
    return status;
  }
  StatusOr<std::vector<bool>> object = SupervoxelGroundTruth(
      captured, maps, [&scene](std::int32_t body) { return scene.IsMoveable(body); });
  if (!object.ok()) return object.status();
  StatusOr<std::vector<std::int32_t>> bodies = SupervoxelBodies(captured, maps);
  if (!bodies.ok()) return bodies.status();

  LabelledFrame labelled;
  labelled.server_ms = maps.timings().total_ms();
  for (int i = 0; i < maps.supervoxels_size(); ++i) {
    const auto& features = maps.supervoxels(i).features();
    // An older server ignores include_features: its rows would have no columns.
    if (features.empty()) {
      return FailedPreconditionError(
          "ComputeMaps returned no features (a server older than "
          "ComputeMapsRequest.include_features?)");
    }
    if (!std::all_of(features.begin(), features.end(),
                     [](double value) { return std::isfinite(value); })) {
      ++labelled.non_finite;
      continue;
    }
    const auto index = static_cast<std::size_t>(i);
    labelled.rows.push_back({frame,
                             (*object)[index],
                             (*bodies)[index],
                             maps.supervoxels(i).object(),
                             {features.begin(), features.end()}});
  }
  return labelled;
}

}  // namespace relmap::sim
