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
  if (e.method == ChangeMethod::kVisibility) {
    return std::to_string(e.target_points) +
           " target points: " + std::to_string(e.supported_points) + " still there, " +
           std::to_string(e.vacated_points) + " vacated, " + std::to_string(e.occluded_points) +
           " occluded; camera motion " + std::to_string(e.camera_rotation_deg) + " deg, " +
           std::to_string(e.camera_translation_m) + " m; " + std::to_string(e.elapsed_ms) + " ms";
  }
  return "difference " + std::to_string(e.difference_points) + " -> " +
         std::to_string(e.after_statistical) + " -> " + std::to_string(e.after_radius) +
         ", ICP fitness " + std::to_string(e.icp_fitness);
}

ChangeDetectorConfig Paper2018() {
  ChangeDetectorConfig config;
  config.method = ChangeMethod::kPaper2018;
  return config;
}

TEST(ChangeDetector, SeesNoChangeBetweenFramesOfAStaticScene) {
  const char* names[] = {"kinect_static_seq_1.pcd", "kinect_static_seq_2.pcd",
                         "kinect_static_seq_3.pcd"};
  std::vector<Cloud> clouds;
  for (const char* name : names) {
    RELMAP_LOAD_REAL_CLOUD(cloud, name);
    clouds.push_back(cloud);
  }
  for (const ChangeDetectorConfig& config : {ChangeDetectorConfig{}, Paper2018()}) {
    for (std::size_t b = 0; b < clouds.size(); ++b) {
      StatusOr<Segmentation> seg = ExtractSupervoxels(clouds[b], SupervoxelConfig{});
      ASSERT_TRUE(seg.ok()) << seg.status().message();
      for (std::size_t a = 0; a < clouds.size(); ++a) {
        if (a == b) continue;
        // Every 30th supervoxel as the target: spread over the whole scene.
        for (std::size_t s = 0; s < seg->supervoxels.size(); s += 30) {
          StatusOr<ChangeEvidence> e = DetectChange(clouds[b], clouds[a], seg->supervoxels,
                                                    static_cast<std::uint32_t>(s), config);
          ASSERT_TRUE(e.ok()) << e.status().message();
          EXPECT_FALSE(e->moved) << ChangeMethodName(config.method) << ", frames " << b + 1
                                 << " -> " << a + 1 << ", supervoxel " << s << ": " << Describe(*e);
        }
      }
    }
  }
}

// The milk carton of milk_cartoon_all_small_clorox.pcd: the points of its image rectangle
// that stand more than 1.5 cm above the floor plane n·x = 1 (fitted on a floor-only region).
struct MilkCarton {
  std::vector<std::size_t> points;
  Eigen::Vector3d floor;  // n
};

MilkCarton FindMilkCarton(const Cloud& cloud) {
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
  return {object, n};
}

struct EditedScene {
  Cloud before, after;
  Supervoxel target;
};

enum class Edit { kShift, kRemove, kHoles };

// Shifts the milk carton by `shift` along x (its old pixels see the floor behind it, its
// shifted points are added: an unorganized after cloud, as a camera would see it once
// projected), removes it (its pixels see the floor), or turns its pixels into holes; the target is
// the carton supervoxel at its trailing edge (smallest x), the side whose space the carton leaves.
void MakeEditedScene(Edit edit, float shift, EditedScene& scene, bool& skip) {
  scene.before = testing::LoadRealCloud("milk_cartoon_all_small_clorox.pcd", skip);
  if (skip) return;
  const MilkCarton carton = FindMilkCarton(scene.before);
  const std::vector<std::size_t>& object = carton.points;
  ASSERT_GT(object.size(), 5000u);
  std::vector<CloudPoint> points = scene.before.points();
  std::vector<bool> is_object(points.size(), false);
  std::vector<CloudPoint> shifted;
  for (std::size_t i : object) {
    is_object[i] = true;
    CloudPoint& p = points[i];
    const Eigen::Vector3d ray(p.x, p.y, p.z);
    switch (edit) {
      case Edit::kShift:
        shifted.push_back(p);
        shifted.back().x += shift;
        [[fallthrough]];
      case Edit::kRemove: {
        const Eigen::Vector3f floor = (ray / carton.floor.dot(ray)).cast<float>();
        p.x = floor.x(), p.y = floor.y(), p.z = floor.z();
        break;
      }
      case Edit::kHoles:
        p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
        break;
    }
  }
  points.insert(points.end(), shifted.begin(), shifted.end());
  StatusOr<Cloud> after = shifted.empty()
                              ? MakeCloud(scene.before.width(), scene.before.height(), points)
                              : MakeCloud(static_cast<std::uint32_t>(points.size()), 1, points);
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
  scene.target = *target;
}

// Both methods label the edited scene's push "moved".
void ExpectMoved(Edit edit, float shift) {
  EditedScene scene;
  bool skip = false;
  MakeEditedScene(edit, shift, scene, skip);
  if (skip) GTEST_SKIP() << "real data not found: " << RELMAP_TEST_DATA_DIR;
  for (const ChangeDetectorConfig& config : {ChangeDetectorConfig{}, Paper2018()}) {
    StatusOr<ChangeEvidence> e = DetectChange(scene.before, scene.after, scene.target, config);
    ASSERT_TRUE(e.ok()) << e.status().message();
    EXPECT_TRUE(e->moved) << ChangeMethodName(config.method) << ": " << Describe(*e);
  }
}

TEST(ChangeDetector, SeesAnObjectDisplacedByThreeCentimetres) { ExpectMoved(Edit::kShift, 0.03f); }

TEST(ChangeDetector, SeesARemovedObject) { ExpectMoved(Edit::kRemove, 0); }

TEST(ChangeDetector, HolesWhereTheTargetWasSayNothingToTheVisibilityTest) {
  EditedScene scene;
  bool skip = false;
  MakeEditedScene(Edit::kHoles, 0, scene, skip);
  if (skip) GTEST_SKIP() << "real data not found: " << RELMAP_TEST_DATA_DIR;
  // A hole is a shadow, an edge or a range limit as often as an empty space: the visibility
  // test does not count it; the octree difference counts every emptied cell.
  StatusOr<ChangeEvidence> e = DetectChange(scene.before, scene.after, scene.target, Paper2018());
  ASSERT_TRUE(e.ok()) << e.status().message();
  EXPECT_TRUE(e->moved) << Describe(*e);
  e = DetectChange(scene.before, scene.after, scene.target, {});
  ASSERT_TRUE(e.ok()) << e.status().message();
  EXPECT_FALSE(e->moved) << Describe(*e);
  EXPECT_EQ(e->supported_points + e->vacated_points + e->occluded_points, 0u) << Describe(*e);
}

TEST(ChangeDetector, SeesNothingWhenNothingChanged) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "milk_cartoon_all_small_clorox.pcd");
  StatusOr<Segmentation> seg = ExtractSupervoxels(cloud, SupervoxelConfig{});
  ASSERT_TRUE(seg.ok());
  for (const ChangeDetectorConfig& config : {ChangeDetectorConfig{}, Paper2018()}) {
    StatusOr<ChangeEvidence> e = DetectChange(cloud, cloud, seg->supervoxels.front(), config);
    ASSERT_TRUE(e.ok());
    EXPECT_FALSE(e->moved);
    EXPECT_EQ(e->difference_points, 0u);
    EXPECT_EQ(e->vacated_points, 0u);
  }
}

TEST(ChangeDetector, RejectsAnEmptyTarget) {
  RELMAP_LOAD_REAL_CLOUD(cloud, "milk_cartoon_all_small_clorox.pcd");
  EXPECT_EQ(DetectChange(cloud, cloud, Supervoxel{}, {}).status().code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::perception
