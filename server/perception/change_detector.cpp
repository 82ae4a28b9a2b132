// Checks the target, times the method the config names, and turns PCL's exceptions into a
// status.
#include "perception/change_detector.h"

#include <chrono>
#include <exception>
#include <string>

#include "perception/change_methods.h"
#include "perception/change_object.h"

namespace relmap::perception {
namespace {

Status CheckPoints(const Cloud& before, const Supervoxel& s) {
  for (const std::int32_t i : s.point_indices) {
    if (i < 0 || static_cast<std::size_t>(i) >= before.size()) {
      return InvalidArgumentError("a supervoxel point lies outside the before cloud");
    }
  }
  return OkStatus();
}

StatusOr<ChangeEvidence> Detect(const Cloud& before, const Cloud& after, const Supervoxel& target,
                                const std::vector<const Supervoxel*>& object,
                                const ChangeDetectorConfig& config,
                                std::chrono::steady_clock::time_point start) {
  if (target.voxels.empty() || target.point_indices.empty()) {
    return InvalidArgumentError("change detection needs a target with points");
  }
  for (const Voxel& v : target.voxels) {
    if (!v.position.allFinite()) return InvalidArgumentError("a target voxel is not finite");
  }
  if (Status status = CheckPoints(before, target); !status.ok()) return status;
  for (const Supervoxel* s : object) {
    if (Status status = CheckPoints(before, *s); !status.ok()) return status;
  }
  ChangeEvidence evidence;
  evidence.method = config.method;
  try {
    if (config.method == ChangeMethod::kPaper2018) {
      DetectByOctreeIcp(before, after, target, config, evidence);
    } else {
      DetectByVisibility(before, after, target, object, config, evidence);
    }
  } catch (const std::exception& ex) {
    return InternalError(std::string("change detection failed: ") + ex.what());
  }
  evidence.elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return evidence;
}

}  // namespace

StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const Supervoxel& target,
                                      const ChangeDetectorConfig& config) {
  return DetectChange(before, after, target, {}, config);
}

StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const Supervoxel& target,
                                      const std::vector<const Supervoxel*>& object,
                                      const ChangeDetectorConfig& config) {
  return Detect(before, after, target, object, config, std::chrono::steady_clock::now());
}

StatusOr<ChangeEvidence> DetectChange(const Cloud& before, const Cloud& after,
                                      const std::vector<Supervoxel>& frame, std::uint32_t target_id,
                                      const ChangeDetectorConfig& config) {
  if (target_id >= frame.size()) {
    return InvalidArgumentError("no supervoxel " + std::to_string(target_id) + " in the frame");
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<const Supervoxel*> object;
  if (config.method == ChangeMethod::kVisibility) {
    for (const std::uint32_t id : ObjectOf(frame, target_id, config.object_smooth_angle_deg)) {
      if (id != target_id) object.push_back(&frame[id]);
    }
  }
  return Detect(before, after, frame[target_id], object, config, start);
}

}  // namespace relmap::perception
