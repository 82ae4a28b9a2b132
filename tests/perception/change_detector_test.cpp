// The change detector of §5 on real Kinect clouds: sensor noise between frames of a static
// scene is no change; an object displaced by 3 cm or removed is.
#include "perception/change_detector.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>

#include "perception/supervoxels.h"
#include "test_data.h"

namespace relmap::perception {
namespace {

std::string Describe(const ChangeEvidence& e) {
  return "difference " + std::to_string(e.difference_points) + " -> " +
         std::to_string(e.after_statistical) + " -> " + std::to_string(e.after_radius) +
         ", ICP fitness " + std::to_string(e.icp_fitness);
}

std::vector<Eigen::Vector3f> VoxelsOf(const Supervoxel& sv) {
  std::vector<Eigen::Vector3f> out;
  for (const Voxel& v : sv.voxels) out.push_back(v.position);
  return out;
}

TEST(ChangeDetector, SeesNoChangeBetweenFramesOfAStaticScene) {
  const char* names[] = {"kinect_static_seq_1.pcd", "kinect_static_seq_2.pcd",
                         "kinect_static_seq_3.pcd"};
  std::vector<Cloud> clouds;
  for (const char* name : names) {
    RELMAP_LOAD_REAL_CLOUD(cloud, name);
    clouds.push_back(cloud);
  }
  const ChangeDetectorConfig config;
  for (std::size_t b = 0; b < clouds.size(); ++b) {
    StatusOr<Segmentation> seg = ExtractSupervoxels(clouds[b], SupervoxelConfig{});
    ASSERT_TRUE(seg.ok()) << seg.status().message();
    for (std::size_t a = 0; a < clouds.size(); ++a) {
      if (a == b) continue;
      // Every 30th supervoxel as the target: spread over the whole scene.
      for (std::size_t s = 0; s < seg->supervoxels.size(); s += 30) {
        StatusOr<ChangeEvidence> e =
            DetectChange(clouds[b], clouds[a], VoxelsOf(seg->supervoxels[s]), config);
        ASSERT_TRUE(e.ok()) << e.status().message();
        EXPECT_FALSE(e->moved) << "frames " << b + 1 << " -> " << a + 1 << ", supervoxel " << s
                               << ": " << Describe(*e);
      }
    }
  }
}

// The milk carton of milk_cartoon_all_small_clorox.pcd: the points of its image rectangle
// that stand more than 1.5 cm above the floor plane (fitted on a floor-only region).
std::vector<std::size_t> MilkCartonPoints(const Cloud& cloud) {
  std::vector<Eigen::Vector3d> floor;
  for (std::uint32_t v = 300; v < 440; v += 4) {
    for (std::uint32_t u = 220; u < 600; u += 4) {
      const CloudPoint p = cloud.point(static_cast<std::size_t>(v) * cloud.width() + u);
      if (std::isfinite(p.x)) floor.emplace_back(p.x, p.y, p.z);
    }
  }
  // Plane n·x = 1 by least squares.
  Eigen::MatrixXd a(static_cast<Eigen::Index>(floor.size()), 3);
  for (std::size_t i = 0; i < floor.size(); ++i) a.row(static_cast<Eigen::Index>(i)) = floor[i];
  const Eigen::Vector3d n = a.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(a.rows()));
  std::vector<std::size_t> object;
  for (std::uint32_t v = 60; v < 235; ++v) {
    for (std::uint32_t u = 228; u < 335; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * cloud.width() + u;
      const CloudPoint p = cloud.point(i);
      if (!std::isfinite(p.x)) continue;
      const double height = std::fabs(n.dot(Eigen::Vector3d(p.x, p.y, p.z)) - 1.0) / n.norm();
      if (height > 0.015) object.push_back(i);
    }
  }
  return object;
}

struct EditedScene {
  Cloud before, after;
  std::vector<Eigen::Vector3f> target;
};

// Moves (or removes, when `shift` is NaN) the milk carton; the target is the carton
// supervoxel at its trailing edge (smallest x), the side whose space the carton leaves.
void MakeEditedScene(float shift, EditedScene& scene, bool& skip) {
  scene.before = testing::LoadRealCloud("milk_cartoon_all_small_clorox.pcd", skip);
  if (skip) return;
  const std::vector<std::size_t> object = MilkCartonPoints(scene.before);
  ASSERT_GT(object.size(), 5000u);
  std::vector<CloudPoint> points = scene.before.points();
  std::vector<bool> is_object(points.size(), false);
  for (std::size_t i : object) {
    is_object[i] = true;
    if (std::isnan(shift)) {
      points[i].x = points[i].y = points[i].z = std::numeric_limits<float>::quiet_NaN();
    } else {
      points[i].x += shift;
    }
  }
  StatusOr<Cloud> after = MakeCloud(scene.before.width(), scene.before.height(), points);
  ASSERT_TRUE(after.ok());
  scene.after = *after;
  StatusOr<Segmentation> seg = ExtractSupervoxels(scene.before, SupervoxelConfig{});
  ASSERT_TRUE(seg.ok());
  const Supervoxel* target = nullptr;
  for (const Supervoxel& sv : seg->supervoxels) {
    std::size_t inside = 0;
    for (std::int32_t i : sv.point_indices) inside += is_object[static_cast<std::size_t>(i)];
    if (10 * inside < 9 * sv.point_indices.size()) continue;
    if (!target || sv.centroid.x() < target->centroid.x()) target = &sv;
  }
  ASSERT_NE(target, nullptr);
  scene.target = VoxelsOf(*target);
}

TEST(ChangeDetector, SeesAnObjectDisplacedByThreeCentimetres) {
  EditedScene scene;
  bool skip = false;
  MakeEditedScene(0.03f, scene, skip);
  if (skip) GTEST_SKIP() << "real data not found: " << RELMAP_TEST_DATA_DIR;
  StatusOr<ChangeEvidence> e = DetectChange(scene.before, scene.after, scene.target, {});
  ASSERT_TRUE(e.ok()) << e.status().message();
  EXPECT_TRUE(e->moved) << Describe(*e);
}

TEST(ChangeDetector, SeesARemovedObject) {
  EditedScene scene;
  bool skip = false;
  MakeEditedScene(std::numeric_limits<float>::quiet_NaN(), scene, skip);
  if (skip) GTEST_SKIP() << "real data not found: " << RELMAP_TEST_DATA_DIR;
  StatusOr<ChangeEvidence> e = DetectChange(scene.before, scene.after, scene.target, {});
  ASSERT_TRUE(e.ok()) << e.status().message();
  EXPECT_TRUE(e->moved) << Describe(*e);
}

TEST(ChangeDetector, SeesNothingWhenNothingChanged) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "milk_cartoon_all_small_clorox.pcd");
  const std::vector<Eigen::Vector3f> target = {{0, 0, 0.8f}, {0.01f, 0, 0.8f}};
  StatusOr<ChangeEvidence> e = DetectChange(cloud, cloud, target, {});
  ASSERT_TRUE(e.ok());
  EXPECT_FALSE(e->moved);
  EXPECT_EQ(e->difference_points, 0u);
}

TEST(ChangeDetector, RejectsAnEmptyTarget) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "milk_cartoon_all_small_clorox.pcd");
  EXPECT_EQ(DetectChange(cloud, cloud, {}, {}).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::perception
