// The target is chosen on the before cloud's frame, as the server does for a push.
#include "change_command.h"

#include <cstdio>
#include <iostream>
#include <string>

#include "perception/change_detector.h"
#include "perception/decode.h"
#include "perception/frame.h"

namespace relmap::tools {
namespace {

int Fail(const std::string& message) {
  std::cerr << "relmap-perception: " << message << "\n";
  return 1;
}

// The supervoxel whose centroid is nearest to `point`, or null for none.
const perception::Supervoxel* NearestSupervoxel(const perception::Frame& frame,
                                                const Eigen::Vector3f& point) {
  const perception::Supervoxel* nearest = nullptr;
  for (const perception::Supervoxel& sv : frame.segmentation.supervoxels) {
    if (!nearest || (sv.centroid - point).norm() < (nearest->centroid - point).norm()) {
      nearest = &sv;
    }
  }
  return nearest;
}

void PrintEvidence(const perception::Supervoxel& target, const perception::ChangeEvidence& e) {
  std::printf(
      "{\"moved\":%s,\"method\":\"%s\",\"target_supervoxel\":%u,"
      "\"target_centroid\":[%.4f,%.4f,%.4f],\"target_points\":%zu,\"supported_points\":%zu,"
      "\"vacated_points\":%zu,\"occluded_points\":%zu,\"difference_points\":%zu,"
      "\"after_statistical\":%zu,\"after_radius\":%zu,\"icp_ran\":%s,\"icp_converged\":%s,"
      "\"icp_fitness\":%.6g,\"change_ms\":%.1f}\n",
      e.moved ? "true" : "false", std::string(perception::ChangeMethodName(e.method)).c_str(),
      target.id, target.centroid.x(), target.centroid.y(), target.centroid.z(), e.target_points,
      e.supported_points, e.vacated_points, e.occluded_points, e.difference_points,
      e.after_statistical, e.after_radius, e.icp_ran ? "true" : "false",
      e.icp_converged ? "true" : "false", e.icp_ran ? e.icp_fitness : -1.0, e.elapsed_ms);
}

}  // namespace

int RunChangeCommand(int argc, char** argv) {
  if (argc != 6 || std::string(argv[4]) != "--target-point") {
    return Fail("usage: relmap-perception --change before.pcd after.pcd --target-point x,y,z");
  }
  float x, y, z;
  if (std::sscanf(argv[5], "%f,%f,%f", &x, &y, &z) != 3) return Fail("bad --target-point");
  const perception::PerceptionConfig config;
  auto before = perception::LoadPcdFile(argv[2], config.limits);
  if (!before.ok()) return Fail(before.status().message());
  auto after = perception::LoadPcdFile(argv[3], config.limits);
  if (!after.ok()) return Fail(after.status().message());
  auto frame = perception::BuildFrame(*before, config);
  if (!frame.ok()) return Fail(frame.status().message());
  const perception::Supervoxel* target = NearestSupervoxel(*frame, Eigen::Vector3f(x, y, z));
  if (!target) return Fail("the before cloud has no supervoxel");
  auto evidence = perception::DetectChange(*before, *after, frame->segmentation.supervoxels,
                                           target->id, config.change);
  if (!evidence.ok()) return Fail(evidence.status().message());
  PrintEvidence(*target, *evidence);
  return 0;
}

}  // namespace relmap::tools
