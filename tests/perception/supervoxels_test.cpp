// VCCS supervoxels: objects of a synthetic scene get supervoxels of their own, the output is
// consistent and deterministic, the crop box applies.
#include "perception/supervoxels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "perception/synthetic_tabletop.h"
#include "test_data.h"

namespace relmap::perception {
namespace {

TEST(Supervoxels, EachObjectFallsMostlyInSupervoxelsOfItsOwn) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  StatusOr<Segmentation> seg = ExtractSupervoxels(scene.cloud, SupervoxelConfig{});
  ASSERT_TRUE(seg.ok()) << seg.status().message();
  // The majority object of every supervoxel.
  std::vector<int> majority(seg->supervoxels.size());
  for (const Supervoxel& sv : seg->supervoxels) {
    std::map<int, int> votes;
    for (std::int32_t i : sv.point_indices)
      ++votes[scene.object_of_point[static_cast<std::size_t>(i)]];
    majority[sv.id] = std::max_element(votes.begin(), votes.end(), [](auto a, auto b) {
                        return a.second < b.second;
                      })->first;
  }
  for (int object = 1; object <= scene.objects; ++object) {
    int labelled = 0, in_own = 0;
    for (std::size_t i = 0; i < scene.object_of_point.size(); ++i) {
      if (scene.object_of_point[i] != object || seg->point_labels[i] < 0) continue;
      ++labelled;
      in_own += majority[static_cast<std::size_t>(seg->point_labels[i])] == object ? 1 : 0;
    }
    ASSERT_GT(labelled, 100) << "object " << object << " is not visible";
    EXPECT_GT(static_cast<double>(in_own) / labelled, 0.85) << "object " << object;
  }
}

TEST(Supervoxels, OutputIsConsistent) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  const SupervoxelConfig config;
  StatusOr<Segmentation> seg = ExtractSupervoxels(scene.cloud, config);
  ASSERT_TRUE(seg.ok()) << seg.status().message();
  ASSERT_GT(seg->supervoxels.size(), 50u);
  std::size_t labelled = 0;
  for (std::int32_t l : seg->point_labels) labelled += l >= 0 ? 1 : 0;
  std::size_t indexed = 0;
  for (std::size_t s = 0; s < seg->supervoxels.size(); ++s) {
    const Supervoxel& sv = seg->supervoxels[s];
    EXPECT_EQ(sv.id, s);
    EXPECT_GE(static_cast<int>(sv.voxels.size()), config.min_voxels);  // §1: small ones dropped
    EXPECT_NEAR(sv.normal.norm(), 1.0f, 1e-3f);
    for (std::int32_t i : sv.point_indices) {
      EXPECT_EQ(seg->point_labels[static_cast<std::size_t>(i)], static_cast<std::int32_t>(s));
    }
    indexed += sv.point_indices.size();
    for (std::uint32_t nb : sv.neighbours) {
      ASSERT_LT(nb, seg->supervoxels.size());
      EXPECT_NE(nb, sv.id);
      const auto& back = seg->supervoxels[nb].neighbours;
      EXPECT_TRUE(std::binary_search(back.begin(), back.end(), sv.id)) << "asymmetric adjacency";
    }
  }
  EXPECT_EQ(indexed, labelled);
  for (std::size_t i = 0; i < scene.object_of_point.size(); ++i) {
    if (scene.object_of_point[i] < 0) {
      EXPECT_EQ(seg->point_labels[i], -1);  // holes
    }
  }
}

// The raw-point FPFH reads the input points through point_indices: with the pre-voxelisation
// too, they must be the raw points, each within two voxel diagonals of a voxel of its
// supervoxel (one from its pre-voxel's mean, one from there to VCCS's voxel mean).
TEST(Supervoxels, PointIndicesAreTheRawPointsWithOrWithoutPrevoxelisation) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  for (bool prevoxelise : {true, false}) {
    SCOPED_TRACE(prevoxelise);
    SupervoxelConfig config;
    config.prevoxelise = prevoxelise;
    StatusOr<Segmentation> seg = ExtractSupervoxels(scene.cloud, config);
    ASSERT_TRUE(seg.ok());
    const float bound = 2.0f * std::sqrt(3.0f) * config.voxel_resolution;
    float worst = 0.0f;
    for (const Supervoxel& sv : seg->supervoxels) {
      for (std::int32_t i : sv.point_indices) {
        const CloudPoint p = scene.cloud.point(static_cast<std::size_t>(i));
        float nearest = std::numeric_limits<float>::infinity();
        for (const Voxel& v : sv.voxels) {
          nearest = std::min(nearest, (v.position - Eigen::Vector3f(p.x, p.y, p.z)).norm());
        }
        worst = std::max(worst, nearest);
      }
    }
    EXPECT_LT(worst, bound);
  }
}

void ExpectIdentical(const Segmentation& a, const Segmentation& b) {
  ASSERT_EQ(a.supervoxels.size(), b.supervoxels.size());
  EXPECT_EQ(a.point_labels, b.point_labels);
  for (std::size_t s = 0; s < a.supervoxels.size(); ++s) {
    EXPECT_EQ(a.supervoxels[s].centroid, b.supervoxels[s].centroid);
    EXPECT_EQ(a.supervoxels[s].neighbours, b.supervoxels[s].neighbours);
    EXPECT_EQ(a.supervoxels[s].voxels.size(), b.supervoxels[s].voxels.size());
  }
}

// PCL's VCCS once ordered voxels by pointer, which made results vary from run to run.
TEST(Supervoxels, AreDeterministic) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  for (bool prevoxelise : {true, false}) {
    SupervoxelConfig config;
    config.prevoxelise = prevoxelise;
    StatusOr<Segmentation> first = ExtractSupervoxels(scene.cloud, config);
    StatusOr<Segmentation> second = ExtractSupervoxels(scene.cloud, config);
    ASSERT_TRUE(first.ok() && second.ok());
    ExpectIdentical(*first, *second);
  }
}

TEST(Supervoxels, AreDeterministicOnARealCloud) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "table_scene_mug_stereo_textured.pcd");
  StatusOr<Segmentation> first = ExtractSupervoxels(cloud, SupervoxelConfig{});
  StatusOr<Segmentation> second = ExtractSupervoxels(cloud, SupervoxelConfig{});
  ASSERT_TRUE(first.ok() && second.ok());
  ExpectIdentical(*first, *second);
}

TEST(Supervoxels, CropBoxLeavesOutsidePointsUnlabelled) {
  const SyntheticTabletop scene = testing::SmallSyntheticScene();
  SupervoxelConfig config;
  config.crop.enabled = true;
  config.crop.min_x = -0.1f, config.crop.max_x = 0.1f;
  config.crop.min_y = -1.0f, config.crop.max_y = 1.0f;
  config.crop.min_z = 0.0f, config.crop.max_z = 5.0f;
  StatusOr<Segmentation> seg = ExtractSupervoxels(scene.cloud, config);
  ASSERT_TRUE(seg.ok()) << seg.status().message();
  ASSERT_GT(seg->supervoxels.size(), 0u);
  for (std::size_t i = 0; i < scene.cloud.size(); ++i) {
    const CloudPoint p = scene.cloud.point(i);
    if (std::isfinite(p.x) && (p.x < -0.1f || p.x > 0.1f)) {
      EXPECT_EQ(seg->point_labels[i], -1);
    }
  }
  config.crop.min_x = 50, config.crop.max_x = 51;
  EXPECT_EQ(ExtractSupervoxels(scene.cloud, config).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::perception
