// The visibility test of docs/method.md §5.1 on a wall facing the camera: each target point
// is still there, seen through, hidden or unseen, by the noise model's tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "perception/change_detector.h"
#include "pinhole_cloud.h"

namespace relmap::perception {
namespace {

using testing::kWidth;

bool InPatch(std::uint32_t u, std::uint32_t v) { return u >= 70 && u < 90 && v >= 50 && v < 70; }

// A wall at depth 1 m; the pixels of the 20x20 patch at the centre are at `patch_depth`.
Cloud Wall(float patch_depth) {
  return testing::PinholeCloud(
      [&](std::uint32_t u, std::uint32_t v) { return InPatch(u, v) ? patch_depth : 1.0f; });
}

Supervoxel Patch() {
  Supervoxel target;
  for (std::uint32_t v = 50; v < 70; ++v) {
    for (std::uint32_t u = 70; u < 90; ++u) {
      target.point_indices.push_back(static_cast<std::int32_t>(v * kWidth + u));
    }
  }
  target.voxels.push_back({Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(0, 0, -1), {0, 0, 0}});
  return target;
}

// The tolerance at 1 m: 3 sqrt(2) sigma(1) + step(1), Kinect v1 figures.
double ToleranceAtOneMetre() {
  const double sigma = 0.0012 + 0.0019 * 0.6 * 0.6;
  return 3.0 * std::sqrt(2.0) * sigma + 1.0 / (8.0 * 580.0 * 0.075);
}

// The patch's outer ring of pixels lies one pixel (7 mm) from the unchanged wall around it,
// within the tolerance of the search window: still there, whatever happened to the patch.
constexpr std::size_t kRing = 20 * 20 - 18 * 18;
constexpr std::size_t kInside = std::size_t{18} * 18;

ChangeEvidence Detect(float patch_depth_after, bool compensate = true) {
  ChangeDetectorConfig config;
  config.compensate_camera_motion = compensate;
  StatusOr<ChangeEvidence> e = DetectChange(Wall(1.0f), Wall(patch_depth_after), Patch(), config);
  EXPECT_TRUE(e.ok()) << e.status().message();
  return e.ok() ? *e : ChangeEvidence{};
}

TEST(VisibilityChange, AnUnchangedWallIsStillThere) {
  const ChangeEvidence e = Detect(1.0f);
  EXPECT_EQ(e.target_points, 400u);
  EXPECT_EQ(e.supported_points, 400u);
  EXPECT_FALSE(e.moved);
  EXPECT_NEAR(e.camera_rotation_deg, 0.0, 1e-3);
}

TEST(VisibilityChange, APatchThatWentBackIsSeenThrough) {
  const ChangeEvidence e = Detect(1.05f);
  EXPECT_EQ(e.vacated_points, kInside);
  EXPECT_EQ(e.supported_points, kRing);
  EXPECT_TRUE(e.moved);
}

TEST(VisibilityChange, SomethingInFrontHidesTheTargetAndIsNoMotion) {
  const ChangeEvidence e = Detect(0.95f);
  EXPECT_EQ(e.occluded_points, kInside);
  EXPECT_EQ(e.supported_points, kRing);
  EXPECT_FALSE(e.moved);
}

TEST(VisibilityChange, OccludedPointsCountNeitherWay) {
  // After: columns 70-84 of the patch 5 cm nearer (something in front), 85-89 5 cm farther.
  // The ring (76 points, one pixel from the unchanged wall) is still there; inside, columns
  // 71-84 are occluded (14 x 18 = 252) and 85-88 vacated (4 x 18 = 72). Vacated are 18 % of
  // the 400 shown points, but 72 / (76 + 72) = 49 % of those that show the target's own
  // surface: moved.
  const Cloud after = testing::PinholeCloud([](std::uint32_t u, std::uint32_t v) {
    if (!InPatch(u, v)) return 1.0f;
    return u < 85 ? 0.95f : 1.05f;
  });
  ChangeDetectorConfig config;
  config.compensate_camera_motion = false;
  const StatusOr<ChangeEvidence> e = DetectChange(Wall(1.0f), after, Patch(), config);
  ASSERT_TRUE(e.ok()) << e.status().message();
  EXPECT_EQ(e->supported_points, kRing);
  EXPECT_EQ(e->occluded_points, 14u * 18u);
  EXPECT_EQ(e->vacated_points, 4u * 18u);
  EXPECT_TRUE(e->moved);
}

TEST(VisibilityChange, HolesSayNothing) {
  const ChangeEvidence e = Detect(std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(e.supported_points, kRing);
  EXPECT_EQ(e.vacated_points + e.occluded_points, 0u);
  EXPECT_FALSE(e.moved);
}

TEST(VisibilityChange, TheToleranceIsTheNoiseModels) {
  const double tolerance = ToleranceAtOneMetre();  // 10.9 mm
  // The patch's points move along their rays: by depth * |ray| > depth; 0.9 and 1.1 of the
  // tolerance in depth keep clear of that on either side (|ray| <= 1.0002 here).
  EXPECT_EQ(Detect(static_cast<float>(1.0 + 0.9 * tolerance), false).supported_points, 400u);
  const ChangeEvidence beyond = Detect(static_cast<float>(1.0 + 1.1 * tolerance), false);
  EXPECT_EQ(beyond.vacated_points, kInside);
  EXPECT_TRUE(beyond.moved);
}

// A motion the client does not count (ChangeDetectorConfig::min_motion) is none: the patch
// pushed back by 1.5 tolerances (16 mm at 1 m) left its inside vacated, which is a move for
// a client that counts every motion; for one that counts only motions over 2 cm, its new
// surface lies within 2 cm of every vacated point, and nothing moved far enough.
TEST(VisibilityChange, AMotionUnderTheSmallestThatCountsIsNone) {
  const auto after = static_cast<float>(1.0 + 1.5 * ToleranceAtOneMetre());
  ChangeDetectorConfig config;
  config.compensate_camera_motion = false;
  StatusOr<ChangeEvidence> any = DetectChange(Wall(1.0f), Wall(after), Patch(), config);
  ASSERT_TRUE(any.ok()) << any.status().message();
  EXPECT_EQ(any->vacated_points, kInside);
  EXPECT_EQ(any->vacated_beyond_motion_points, kInside);
  EXPECT_TRUE(any->moved);
  config.min_motion = 0.02;
  StatusOr<ChangeEvidence> counted = DetectChange(Wall(1.0f), Wall(after), Patch(), config);
  ASSERT_TRUE(counted.ok()) << counted.status().message();
  EXPECT_EQ(counted->vacated_points, kInside);  // the share is the noise's
  EXPECT_EQ(counted->vacated_beyond_motion_points, 0u);
  EXPECT_FALSE(counted->moved);
}

// A box 10 cm in front of the wall (the patch at 0.9 m) slid 8 pixels to the right, each
// 0.9 / 140 m = 6.4 mm: 51 mm. Columns 70-76 see the wall 10 cm behind (column 77 is one
// pixel, 6.4 mm, from the box's new edge at 78, within the noise's 9.4 mm): 7 x 20 vacated
// whatever min_motion is. Which of them moved farther than min_motion is looked for over
// min_motion * 140 / 0.9 pixels.
ChangeEvidence DetectSlid(double min_motion) {
  constexpr std::uint32_t kColumns = 8;
  const Cloud before = Wall(0.9f);
  const Cloud after = testing::PinholeCloud([&](std::uint32_t u, std::uint32_t v) {
    return u >= 70 + kColumns && InPatch(u - kColumns, v) ? 0.9f : 1.0f;
  });
  ChangeDetectorConfig config;
  config.compensate_camera_motion = false;
  config.min_motion = min_motion;
  StatusOr<ChangeEvidence> e = DetectChange(before, after, Patch(), config);
  EXPECT_TRUE(e.ok()) << e.status().message();
  EXPECT_EQ(e.ok() ? e->vacated_points : 0u, 7u * 20u);
  return e.ok() ? *e : ChangeEvidence{};
}

TEST(VisibilityChange, TheSmallestMotionThatCountsIsLookedForSideways) {
  const ChangeEvidence any = DetectSlid(0.0);
  EXPECT_EQ(any.vacated_beyond_motion_points, 7u * 20u);
  EXPECT_TRUE(any.moved);
  // Over 6 cm: a window of ceil(0.06 * 140 / 0.9) = 10 pixels reaches each vacated point's
  // new place, 51 mm away: none moved far enough.
  const ChangeEvidence under = DetectSlid(0.06);
  EXPECT_EQ(under.vacated_beyond_motion_points, 0u);
  EXPECT_FALSE(under.moved);
  // Over 2 cm: a window of 4 pixels, and columns 70-74 are farther than 2 cm from the box's
  // new edge (column 75 is 3 pixels, 19.3 mm, from it): 5 x 20, a move.
  const ChangeEvidence over = DetectSlid(0.02);
  EXPECT_EQ(over.vacated_beyond_motion_points, 5u * 20u);
  EXPECT_TRUE(over.moved);
}

// The supervoxel of the 20x20 pixels from column u0, rows 50-69, with id `id`.
Supervoxel PatchAt(std::uint32_t u0, std::uint32_t id) {
  Supervoxel patch;
  patch.id = id;
  for (std::uint32_t v = 50; v < 70; ++v) {
    for (std::uint32_t u = u0; u < u0 + 20; ++u) {
      patch.point_indices.push_back(static_cast<std::int32_t>(v * kWidth + u));
    }
  }
  patch.voxels.push_back({Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(0, 0, -1), {0, 0, 0}});
  return patch;
}

// The target (columns 70-89) and its object's part 5 (90-109) went back 5 cm; part 7
// (30-49) stayed; part 9 (110-129) is hidden behind something 5 cm nearer. Only part 5
// left its place: it alone is named as moved with the target.
TEST(VisibilityChange, NamesTheObjectsOtherPartsThatMoved) {
  const Cloud after = testing::PinholeCloud([](std::uint32_t u, std::uint32_t v) {
    if (v < 50 || v >= 70) return 1.0f;
    if (u >= 70 && u < 110) return 1.05f;
    return u >= 110 && u < 130 ? 0.95f : 1.0f;
  });
  const Supervoxel target = PatchAt(70, 0), went = PatchAt(90, 5), stayed = PatchAt(30, 7),
                   hidden = PatchAt(110, 9);
  ChangeDetectorConfig config;
  config.compensate_camera_motion = false;
  const StatusOr<ChangeEvidence> e =
      DetectChange(Wall(1.0f), after, target, {&hidden, &stayed, &went}, config);
  ASSERT_TRUE(e.ok()) << e.status().message();
  EXPECT_TRUE(e->moved);
  EXPECT_EQ(e->moved_supervoxels, std::vector<std::uint32_t>{5});
  // A target that did not move names nothing.
  const StatusOr<ChangeEvidence> still =
      DetectChange(Wall(1.0f), Wall(1.0f), target, {&hidden, &stayed, &went}, config);
  ASSERT_TRUE(still.ok()) << still.status().message();
  EXPECT_FALSE(still->moved);
  EXPECT_TRUE(still->moved_supervoxels.empty());
}

}  // namespace
}  // namespace relmap::perception
