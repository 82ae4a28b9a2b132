// Shared inputs of the perception tests: the real Kinect clouds (skipped when absent) and
// a small synthetic scene.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "perception/decode.h"
#include "perception/supervoxels.h"
#include "perception/synthetic_tabletop.h"

namespace relmap::perception::testing {

inline std::string RealCloudPath(const std::string& name) {
  return std::string(RELMAP_TEST_DATA_DIR) + "/" + name;
}

// Loads a real cloud, or sets `skip` when the data directory is not there (a clone without
// ../shared/data): the caller then GTEST_SKIPs.
inline Cloud LoadRealCloud(const std::string& name, bool& skip) {
  const std::string path = RealCloudPath(name);
  skip = !std::filesystem::exists(path);
  if (skip) return Cloud();
  StatusOr<Cloud> cloud = LoadPcdFile(path);
  EXPECT_TRUE(cloud.ok()) << cloud.status().message();
  return cloud.ok() ? *cloud : Cloud();
}

// The 320x240 synthetic tabletop: fast enough for every unit test.
inline SyntheticTabletop SmallSyntheticScene() {
  SyntheticTabletopOptions options;
  options.width = 320;
  options.height = 240;
  return MakeSyntheticTabletop(options);
}

// The voxels with a finite normal of the small synthetic scene's segmentation: the point
// set the FPFH kernels work on.
inline void SmallSceneVoxels(std::vector<Eigen::Vector3f>& positions,
                             std::vector<Eigen::Vector3f>& normals) {
  StatusOr<Segmentation> seg = ExtractSupervoxels(SmallSyntheticScene().cloud, SupervoxelConfig{});
  ASSERT_TRUE(seg.ok()) << seg.status().message();
  for (const Supervoxel& sv : seg->supervoxels) {
    for (const Voxel& v : sv.voxels) {
      if (!v.normal.allFinite()) continue;
      positions.push_back(v.position);
      normals.push_back(v.normal);
    }
  }
}

#define RELMAP_LOAD_REAL_CLOUD(var, name)                                          \
  bool var##_skip = false;                                                         \
  const ::relmap::perception::Cloud var =                                          \
      ::relmap::perception::testing::LoadRealCloud(name, var##_skip);              \
  if (var##_skip) GTEST_SKIP() << "real data not found: " << RELMAP_TEST_DATA_DIR; \
  ASSERT_GT((var).size(), 0u)

}  // namespace relmap::perception::testing
