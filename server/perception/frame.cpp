// BuildFrame: supervoxels then features, timed per stage.
#include "perception/frame.h"

#include <chrono>

#include "perception/change_object.h"

namespace relmap::perception {

StatusOr<Frame> BuildFrame(Cloud cloud, const PerceptionConfig& config) {
  if (Status status = Validate(config); !status.ok()) return status;
  const auto start = std::chrono::steady_clock::now();
  StatusOr<Segmentation> segmentation = ExtractSupervoxels(cloud, config.supervoxels);
  if (!segmentation.ok()) return segmentation.status();
  Frame frame;
  frame.cloud = std::move(cloud);
  frame.segmentation = std::move(segmentation).value();
  frame.timings.filter_ms = frame.segmentation.filter_ms;
  frame.timings.supervoxels_ms = frame.segmentation.supervoxels_ms;
  frame.timings.normals_ms = frame.segmentation.normals_ms;
  frame.objects =
      ObjectLabels(frame.segmentation.supervoxels, config.change.object_smooth_angle_deg);
  const auto features_start = std::chrono::steady_clock::now();
  frame.features =
      ComputeFeatures(frame.cloud, frame.segmentation, config.features, config.threads);
  const auto end = std::chrono::steady_clock::now();
  frame.timings.features_ms =
      std::chrono::duration<double, std::milli>(end - features_start).count();
  frame.timings.total_ms = std::chrono::duration<double, std::milli>(end - start).count();
  return frame;
}

}  // namespace relmap::perception
