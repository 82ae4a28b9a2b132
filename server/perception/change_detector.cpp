// Checks the target, times the method the config names, and turns PCL's exceptions into a
// status.
#include "perception/change_detector.h"

#include <chrono>
#include <exception>
#include <string>

#include "perception/change_methods.h"

namespace relmap::perception {

StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const Supervoxel& target,
                                      const ChangeDetectorConfig& config) {
  if (target.voxels.empty() || target.point_indices.empty()) {
    return InvalidArgumentError("change detection needs a target with points");
  }
  for (const Voxel& v : target.voxels) {
    if (!v.position.allFinite()) return InvalidArgumentError("a target voxel is not finite");
  }
  for (const std::int32_t i : target.point_indices) {
    if (i < 0 || static_cast<std::size_t>(i) >= before.size()) {
      return InvalidArgumentError("a target point lies outside the before cloud");
    }
  }
  const auto start = std::chrono::steady_clock::now();
  ChangeEvidence evidence;
  evidence.method = config.method;
  try {
    if (config.method == ChangeMethod::kPaper2018) {
      DetectByOctreeIcp(before, after, target, config, evidence);
    } else {
      DetectByVisibility(before, after, target, config, evidence);
    }
  } catch (const std::exception& ex) {
    return InternalError(std::string("change detection failed: ") + ex.what());
  }
  evidence.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return evidence;
}

}  // namespace relmap::perception
