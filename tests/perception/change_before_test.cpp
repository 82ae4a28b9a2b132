// The compact frame a session caches (compact_cloud.h, change_before.h): it gives back
// every coordinate bit for bit, and the change detector's answer on it is the answer on
// the full frame.
#include "perception/change_before.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "perception/change_detector.h"
#include "perception/supervoxels.h"
#include "test_data.h"

namespace relmap::perception {
namespace {

std::uint32_t Bits(float v) { return std::bit_cast<std::uint32_t>(v); }

// Every point of `expanded` is the point of `original`: the same holes, the same bits of
// x, y, z, and the same colour when `colour`.
void ExpectSameCloud(const Cloud& original, const Cloud& expanded, bool colour) {
  ASSERT_EQ(expanded.width(), original.width());
  ASSERT_EQ(expanded.height(), original.height());
  ASSERT_EQ(expanded.valid_points(), original.valid_points());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < original.size(); ++i) {
    const CloudPoint a = original.point(i), b = expanded.point(i);
    const bool finite = std::isfinite(a.z);
    const bool same_hole = finite == std::isfinite(b.z);
    const bool same_point = Bits(a.x) == Bits(b.x) && Bits(a.y) == Bits(b.y) &&
                            Bits(a.z) == Bits(b.z) &&
                            (!colour || (a.r == b.r && a.g == b.g && a.b == b.b));
    if (!same_hole || (finite && !same_point)) ++differing;
  }
  EXPECT_EQ(differing, 0u);
}

TEST(CompactCloud, GivesBackEveryRealCloudBitForBitInAFractionOfItsSize) {
  for (const char* name : {"kinect_static_seq_1.pcd", "milk_cartoon_all_small_clorox.pcd",
                           "table_scene_mug_stereo_textured.pcd"}) {
    RELMAP_LOAD_REAL_CLOUD(cloud, name);
    for (const bool colour : {false, true}) {
      const CompactCloud compact = CompactCloud::Of(cloud, colour);
      StatusOr<Cloud> expanded = compact.Expand();
      ASSERT_TRUE(expanded.ok()) << expanded.status().message();
      ExpectSameCloud(cloud, *expanded, colour);
      // x, y, z and r, g, b of every point raw would take 15 bytes a point (PCL's take
      // 32): the prediction leaves under 4 (measured: 0.8-2.2 without colour).
      EXPECT_LT(compact.bytes(), 4 * cloud.size()) << name;
    }
  }
}

TEST(CompactCloud, GivesBackAnUnorganizedCloudWithoutColour) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // No pixel grid: x and y are predicted by the previous point; signs, a negative zero and
  // a tiny value must survive the bit differences.
  const std::vector<CloudPoint> points = {{0.5f, -0.25f, 1.0f, 10, 20, 30},
                                          {nan, nan, nan, 1, 2, 3},
                                          {-0.0f, 1e-30f, 2.5f, 40, 50, 60},
                                          {-3.0f, 0.125f, 0.75f, 70, 80, 90}};
  StatusOr<Cloud> cloud = MakeCloud(4, 1, points);
  ASSERT_TRUE(cloud.ok());
  const CompactCloud compact = CompactCloud::Of(*cloud, false);
  StatusOr<Cloud> expanded = compact.Expand();
  ASSERT_TRUE(expanded.ok()) << expanded.status().message();
  ExpectSameCloud(*cloud, *expanded, false);
  EXPECT_EQ(expanded->point(2).r, 0);  // colours were not kept
  EXPECT_TRUE(std::signbit(expanded->point(2).x));
}

void ExpectSameEvidence(const ChangeEvidence& full, const ChangeEvidence& compact,
                        const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(compact.moved, full.moved);
  EXPECT_EQ(compact.target_points, full.target_points);
  EXPECT_EQ(compact.supported_points, full.supported_points);
  EXPECT_EQ(compact.vacated_points, full.vacated_points);
  EXPECT_EQ(compact.occluded_points, full.occluded_points);
  EXPECT_EQ(compact.object_supervoxels, full.object_supervoxels);
  EXPECT_EQ(compact.object_points, full.object_points);
  EXPECT_EQ(compact.object_supported_points, full.object_supported_points);
  EXPECT_EQ(compact.object_vacated_points, full.object_vacated_points);
  EXPECT_EQ(compact.object_occluded_points, full.object_occluded_points);
  EXPECT_EQ(compact.camera_rotation_deg, full.camera_rotation_deg);
  EXPECT_EQ(compact.camera_translation_m, full.camera_translation_m);
  EXPECT_EQ(compact.difference_points, full.difference_points);
  EXPECT_EQ(compact.after_statistical, full.after_statistical);
  EXPECT_EQ(compact.after_radius, full.after_radius);
  EXPECT_EQ(compact.icp_ran, full.icp_ran);
  EXPECT_EQ(compact.icp_converged, full.icp_converged);
  EXPECT_EQ(compact.icp_fitness, full.icp_fitness);
}

// `cloud` with the points of `target` pushed 5 cm back along their rays: the target left,
// and what the camera now sees there is farther (a push that moved it out of view).
Cloud WithTargetGone(const Cloud& cloud, const Supervoxel& target) {
  std::vector<CloudPoint> points = cloud.points();
  for (const std::int32_t i : target.point_indices) {
    CloudPoint& p = points[static_cast<std::size_t>(i)];
    const float scale = 1.0f + 0.05f / std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    p.x *= scale, p.y *= scale, p.z *= scale;
  }
  StatusOr<Cloud> after = MakeCloud(cloud.width(), cloud.height(), points);
  EXPECT_TRUE(after.ok());
  return after.ok() ? *after : Cloud();
}

std::vector<ChangeDetectorConfig> EveryMethod() {
  ChangeDetectorConfig visibility, with_colour, paper;
  with_colour.colour_tolerance = 40;
  paper.method = ChangeMethod::kPaper2018;
  return {visibility, with_colour, paper};
}

// `cloud` and its supervoxels (default settings): all of a frame that ChangeBefore reads.
StatusOr<Frame> SegmentedFrame(const Cloud& cloud) {
  StatusOr<Segmentation> segmentation = ExtractSupervoxels(cloud, SupervoxelConfig{});
  if (!segmentation.ok()) return segmentation.status();
  Frame frame;
  frame.cloud = cloud;
  frame.segmentation = *segmentation;
  return frame;
}

TEST(ChangeBefore, GivesTheChangeDetectorsAnswerOfTheFullFrame) {
  RELMAP_LOAD_REAL_CLOUD(mug, "table_scene_mug_stereo_textured.pcd");
  RELMAP_LOAD_REAL_CLOUD(static_1, "kinect_static_seq_1.pcd");
  RELMAP_LOAD_REAL_CLOUD(static_2, "kinect_static_seq_2.pcd");
  std::size_t moved = 0, stayed = 0, larger_objects = 0;
  // The mug scene with a target gone (moved), and two frames of a static scene from a
  // camera that moved a little (not moved, after the camera-motion compensation).
  for (const Cloud* before : {&mug, &static_1}) {
    StatusOr<Frame> frame = SegmentedFrame(*before);
    ASSERT_TRUE(frame.ok()) << frame.status().message();
    const std::vector<Supervoxel>& supervoxels = frame->segmentation.supervoxels;
    for (const ChangeDetectorConfig& config : EveryMethod()) {
      const ChangeBefore compact = ChangeBefore::Of(*frame, config);
      ASSERT_EQ(compact.supervoxels(), supervoxels.size());
      // Every 60th supervoxel: spread over the scene, few enough for the octree method.
      for (std::size_t s = 0; s < supervoxels.size(); s += 60) {
        const Supervoxel& target = supervoxels[s];
        StatusOr<ChangeInput> input = compact.Expand(static_cast<std::uint32_t>(s));
        ASSERT_TRUE(input.ok()) << input.status().message();
        EXPECT_EQ(input->target.point_indices, target.point_indices);
        ASSERT_EQ(input->target.voxels.size(), target.voxels.size());
        const Cloud after = before == &mug ? WithTargetGone(mug, target) : static_2;
        // The full frame finds the target's object itself; the packed one kept it.
        StatusOr<ChangeEvidence> full =
            DetectChange(*before, after, supervoxels, static_cast<std::uint32_t>(s), config);
        StatusOr<ChangeEvidence> packed =
            DetectChange(input->before, after, input->target, input->ObjectPointers(), config);
        ASSERT_TRUE(full.ok() && packed.ok());
        ExpectSameEvidence(*full, *packed,
                           std::string(ChangeMethodName(config.method)) + " colour " +
                               std::to_string(config.colour_tolerance) + ", supervoxel " +
                               std::to_string(s) + (before == &mug ? " of the mug" : " of static"));
        ++(full->moved ? moved : stayed);
        larger_objects += full->object_supervoxels > 1;
      }
    }
  }
  // Both answers were compared, not one of them only, and objects of several supervoxels.
  EXPECT_GT(moved, 0u);
  EXPECT_GT(stayed, 0u);
  EXPECT_GT(larger_objects, 0u);
}

TEST(ChangeBefore, TakesUnderAMegabyteForAKinectFrame) {
  RELMAP_LOAD_REAL_CLOUD(mug, "table_scene_mug_stereo_textured.pcd");
  StatusOr<Frame> frame = SegmentedFrame(mug);
  ASSERT_TRUE(frame.ok());
  // The decoded cloud alone is 640 x 480 x 32 bytes = 9.8 MB.
  EXPECT_LT(ChangeBefore::Of(*frame, ChangeDetectorConfig{}).bytes(), 1u << 20);
}

TEST(ChangeBefore, RefusesASupervoxelTheFrameDoesNotHave) {
  RELMAP_LOAD_REAL_CLOUD(mug, "table_scene_mug_stereo_textured.pcd");
  StatusOr<Frame> frame = SegmentedFrame(mug);
  ASSERT_TRUE(frame.ok());
  const ChangeBefore compact = ChangeBefore::Of(*frame, ChangeDetectorConfig{});
  const auto past_the_last = static_cast<std::uint32_t>(frame->segmentation.supervoxels.size());
  EXPECT_EQ(compact.Expand(past_the_last).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::perception
