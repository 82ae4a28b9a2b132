// The object evidence of docs/method.md §5.1: the target's object grown through locally
// convex or smooth connections (LCCP), and a push judged by what the object shows. Hand-made
// fronto-parallel scenes: a wall at 1 m, boxes whose faces stand in front of it.
#include "perception/change_object.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "perception/change_detector.h"
#include "pinhole_cloud.h"

namespace relmap::perception {
namespace {

Supervoxel At(const Eigen::Vector3f& centroid, const Eigen::Vector3f& normal) {
  Supervoxel s;
  s.centroid = centroid;
  s.normal = normal;
  return s;
}

TEST(OnOneObject, AConvexEdgeJoins) {
  // A box's top (normal up) and its side (normal out): d = (a - b)/|a - b| = (-1, 1, 0)/sqrt 2,
  // n_a . d = 1/sqrt 2 > n_b . d = -1/sqrt 2.
  const Supervoxel top = At({0, 1, 0}, {0, 1, 0}), side = At({1, 0, 0}, {1, 0, 0});
  EXPECT_TRUE(OnOneObject(top, side, 10.0));
  EXPECT_TRUE(OnOneObject(side, top, 10.0));
}

TEST(OnOneObject, AConcaveCreaseSeparates) {
  // A table (normal up) and the side of a brick standing on it, facing the table's part:
  // d = (1, -1, 0)/sqrt 2, n_a . d = -1/sqrt 2 < n_b . d = 1/sqrt 2, normals 90 degrees apart.
  const Supervoxel table = At({1, 0, 0}, {0, 1, 0}), side = At({0, 1, 0}, {1, 0, 0});
  EXPECT_FALSE(OnOneObject(table, side, 10.0));
  EXPECT_FALSE(OnOneObject(side, table, 10.0));
}

TEST(OnOneObject, ASlightlyConcaveSurfaceIsSmooth) {
  // Two patches of a surface bent 5 (then 15) degrees concavely: joined within a 10 degree
  // tolerance only when bent less.
  const auto bent = [](double degrees) {
    const double r = degrees * std::numbers::pi / 180.0;
    return At({1, 0, 0}, {static_cast<float>(-std::sin(r)), static_cast<float>(std::cos(r)), 0});
  };
  const Supervoxel flat = At({0, 0, 0}, {0, 1, 0});
  EXPECT_TRUE(OnOneObject(flat, bent(5.0), 10.0));
  EXPECT_FALSE(OnOneObject(flat, bent(15.0), 10.0));
}

TEST(ObjectOf, StopsAtAConcaveCrease) {
  // a - b convex (a box's top and side), b - c concave (the side and the table), c - d flat.
  std::vector<Supervoxel> frame = {At({0, 1, 0}, {0, 1, 0}), At({1, 0, 0}, {1, 0, 0}),
                                   At({2, -1, 0}, {0, 1, 0}), At({3, -1, 0}, {0, 1, 0})};
  frame[1].centroid = {1, 0.5f, 0};
  frame[2].centroid = {2, -0.5f, 0};
  const std::vector<std::vector<std::uint32_t>> adjacency = {{1}, {0, 2}, {1, 3}, {2}};
  for (std::uint32_t i = 0; i < frame.size(); ++i) {
    frame[i].id = i;
    frame[i].neighbours = adjacency[i];
  }
  EXPECT_EQ(ObjectOf(frame, 0, 10.0), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(ObjectOf(frame, 3, 10.0), (std::vector<std::uint32_t>{3, 2}));
}

using testing::kWidth;

// A wall at 1 m with a box face 10 cm in front of it over columns [u0, u1) and rows [v0, v1).
Cloud BoxOnWall(std::uint32_t u0, std::uint32_t u1, std::uint32_t v0, std::uint32_t v1) {
  return testing::PinholeCloud([=](std::uint32_t u, std::uint32_t v) {
    return u >= u0 && u < u1 && v >= v0 && v < v1 ? 0.9f : 1.0f;
  });
}

struct Rect {
  std::uint32_t u0, u1, v0, v1;
};

// Supervoxels of `cloud` over pixel rectangles, all facing the camera (a fronto-parallel
// scene: every connection is smooth), adjacent as `adjacency` says (VCCS's voxel adjacency:
// the wall 10 cm behind a box face does not touch it).
std::vector<Supervoxel> Supervoxels(const Cloud& cloud, const std::vector<Rect>& rects,
                                    const std::vector<std::vector<std::uint32_t>>& adjacency) {
  std::vector<Supervoxel> frame(rects.size());
  for (std::uint32_t i = 0; i < rects.size(); ++i) {
    Supervoxel& s = frame[i];
    s.id = i;
    s.normal = {0, 0, -1};
    s.neighbours = adjacency[i];
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    for (std::uint32_t v = rects[i].v0; v < rects[i].v1; ++v) {
      for (std::uint32_t u = rects[i].u0; u < rects[i].u1; ++u) {
        const std::size_t index = static_cast<std::size_t>(v) * kWidth + u;
        s.point_indices.push_back(static_cast<std::int32_t>(index));
        const CloudPoint p = cloud.point(index);
        sum += Eigen::Vector3f(p.x, p.y, p.z);
      }
    }
    s.centroid = sum / static_cast<float>(s.point_indices.size());
    s.voxels.push_back({s.centroid, s.normal, {0, 0, 0}});
  }
  return frame;
}

ChangeDetectorConfig StillCamera() {
  ChangeDetectorConfig config;
  config.compensate_camera_motion = false;
  return config;
}

ChangeEvidence Detect(const Cloud& before, const Cloud& after, const std::vector<Supervoxel>& frame,
                      std::uint32_t target) {
  StatusOr<ChangeEvidence> e = DetectChange(before, after, frame, target, StillCamera());
  EXPECT_TRUE(e.ok()) << e.status().message();
  return e.ok() ? *e : ChangeEvidence{};
}

ChangeEvidence DetectAlone(const Cloud& before, const Cloud& after, const Supervoxel& target) {
  StatusOr<ChangeEvidence> e = DetectChange(before, after, target, StillCamera());
  EXPECT_TRUE(e.ok()) << e.status().message();
  return e.ok() ? *e : ChangeEvidence{};
}

TEST(ObjectEvidence, ABoxSlidAlongItsOwnFaceMovedWithItsTrailingPart) {
  // The box face (columns 40-99, rows 40-79, 0.9 m) slides 20 columns along its own plane.
  // The target, columns 80-99, sees the same face at the same depth after: 800 points still
  // there. Its object is the face's three supervoxels. Of the trailing one (40-59), column 59
  // is 1 pixel (6.4 mm at 0.9 m, under the 10.9 mm tolerance) from the face's new edge:
  // still there; columns 40-58 see the wall behind: 19 x 40 = 760 vacated, 760 / 2400 = 32 %
  // of the object's shown surface.
  const Cloud before = BoxOnWall(40, 100, 40, 80), after = BoxOnWall(60, 120, 40, 80);
  const std::vector<Supervoxel> frame = Supervoxels(
      before, {{40, 60, 40, 80}, {60, 80, 40, 80}, {80, 100, 40, 80}}, {{1}, {0, 2}, {1}});
  const ChangeEvidence e = Detect(before, after, frame, 2);
  EXPECT_EQ(e.supported_points, 800u);
  EXPECT_EQ(e.vacated_points, 0u);
  EXPECT_EQ(e.object_supervoxels, 3u);
  EXPECT_EQ(e.object_points, 2400u);
  EXPECT_EQ(e.object_vacated_points, 760u);
  EXPECT_EQ(e.object_supported_points, 1640u);
  EXPECT_TRUE(e.moved);
  EXPECT_FALSE(DetectAlone(before, after, frame[2]).moved);
}

TEST(ObjectEvidence, AStraddlingSupervoxelTakesNoMotionFromAMovedNeighbour) {
  // A box face over columns 40-63 leaves; the target spans columns 60-89: 4 x 40 = 160 of its
  // 1200 points on the box (vacated), 1040 on the wall (still there): 13 % vacated, under
  // 20 %. Through it, the box and the wall are one object (every connection here is smooth):
  // the box's 800 + 160 vacated of 800 + 1200 + the wall's 70 x 120 = 8400 points is 9.2 %,
  // under 20 % too. The box's own supervoxel, wholly vacated, did move.
  const Cloud before = BoxOnWall(40, 64, 40, 80), after = BoxOnWall(0, 0, 0, 0);
  const std::vector<Supervoxel> frame = Supervoxels(
      before, {{40, 60, 40, 80}, {60, 90, 40, 80}, {90, 160, 0, 120}}, {{1}, {0, 2}, {1}});
  const ChangeEvidence e = Detect(before, after, frame, 1);
  EXPECT_EQ(e.vacated_points, 160u);
  EXPECT_EQ(e.supported_points, 1040u);
  EXPECT_EQ(e.object_points, 10400u);
  EXPECT_EQ(e.object_vacated_points, 960u);
  EXPECT_FALSE(e.moved);
  EXPECT_TRUE(Detect(before, after, frame, 0).moved);
}

TEST(ObjectEvidence, ASmallObjectIsJudgedWhole) {
  // A 5 x 4 pixel box (columns 70-74, rows 60-63) leaves: its target supervoxel, columns
  // 70-71, has 8 points vacated, fewer than the 10 that a camera's revealed strip can reach;
  // the object, 20 vacated of 20.
  const Cloud before = BoxOnWall(70, 75, 60, 64), after = BoxOnWall(0, 0, 0, 0);
  const std::vector<Supervoxel> frame =
      Supervoxels(before, {{70, 72, 60, 64}, {72, 75, 60, 64}}, {{1}, {0}});
  const ChangeEvidence e = Detect(before, after, frame, 0);
  EXPECT_EQ(e.vacated_points, 8u);
  EXPECT_EQ(e.object_vacated_points, 20u);
  EXPECT_TRUE(e.moved);
  EXPECT_FALSE(DetectAlone(before, after, frame[0]).moved);
}

// A wall at 1 m; a flat box face at 0.9 m over columns [flat_from, 60) and, flush against it,
// a roof-shaped box over columns [60 + shift, 90 + shift): its ridge, 15 columns in, is
// 3 mm nearer per column (25 degrees from the image plane), so that its two faces pin down
// a sideways motion. Rows 40-79. `flat_shift` moves the flat box too.
Cloud FlatBesideRoof(std::uint32_t flat_from, std::uint32_t shift, std::uint32_t flat_shift) {
  return testing::PinholeCloud([=](std::uint32_t u, std::uint32_t v) {
    if (v < 40 || v >= 80) return 1.0f;
    if (u >= flat_from + flat_shift && u < 60 + flat_shift) return 0.9f;
    if (u >= 60 + shift && u < 90 + shift) {
      const float from_ridge = std::fabs(static_cast<float>(u - shift) - 74.5f);
      return 0.9f - 0.003f * (15.0f - from_ridge);
    }
    return 1.0f;
  });
}

std::vector<Supervoxel> FlatAndRoof(const Cloud& before, std::uint32_t flat_from) {
  // The flat face, then the roof's two faces; adjacent in a row, one object.
  return Supervoxels(before, {{flat_from, 60, 40, 80}, {60, 75, 40, 80}, {75, 90, 40, 80}},
                     {{1}, {0, 2}, {1}});
}

TEST(ObjectEvidence, ABodyFlushAgainstThePushedOneStayed) {
  // The roof slides 5 columns (32 mm at 0.9 m) away from the flat box, which stays: the
  // flat face's 400 points are all still there, but its object (joined through the roof)
  // shows the roof's move. The motion fitted to the roof's faces (within 2 mm of the true
  // one: 30.7 mm, 0.4 degrees) would carry the flat face 4.8 columns along, onto columns
  // 55-64; the after frame shows the wall at columns 60-64, and the 3 columns of those
  // farther than the tolerance (10.9 mm) from the face's edge are seen through: 120 of 400
  // points, 30 %, against none at its old place. Pooled share 120 / 800 = 0.15, standard
  // error sqrt(0.15 x 0.85 x 2 / 400) = 0.025: z = 0.3 / 0.025 = 11.9, over 3. The flat
  // face did not go with the roof.
  const Cloud before = FlatBesideRoof(50, 0, 0), after = FlatBesideRoof(50, 5, 0);
  const std::vector<Supervoxel> frame = FlatAndRoof(before, 50);
  const ChangeEvidence e = Detect(before, after, frame, 0);
  EXPECT_EQ(e.supported_points, 400u);
  EXPECT_TRUE(e.object_motion_fitted);
  EXPECT_NEAR(e.object_motion_translation_m, 5 * 0.9 / testing::kFocal, 0.002);
  EXPECT_LT(e.object_motion_rotation_deg, 1.0);
  EXPECT_EQ(e.carried_vacated_points, 120u);
  EXPECT_EQ(e.carried_supported_points, 280u);
  EXPECT_FALSE(e.moved);
  // The roof's own faces moved.
  EXPECT_TRUE(Detect(before, after, frame, 1).moved);
}

TEST(ObjectEvidence, ABodyPushedAlongWithItsNeighbourMoved) {
  // Both slide 5 columns; the flat face is 30 columns wide, so its own points see the wall
  // only at its trailing columns 30-33 (column 34 is 1 pixel, 6.4 mm, from the face's new
  // edge: still there): 160 of 1200, 13 %, under the 20 % of a move. Carried by the roof's
  // motion it lands on its own new place: it went with its object.
  const Cloud before = FlatBesideRoof(30, 0, 0), after = FlatBesideRoof(30, 5, 5);
  const std::vector<Supervoxel> frame = FlatAndRoof(before, 30);
  const ChangeEvidence e = Detect(before, after, frame, 0);
  EXPECT_EQ(e.vacated_points, 160u);
  EXPECT_TRUE(e.object_motion_fitted);
  EXPECT_LT(e.carried_vacated_points, 1200u / 5);
  EXPECT_TRUE(e.moved);
}

TEST(ObjectEvidence, AStaticSceneDidNotMove) {
  const Cloud scene = BoxOnWall(40, 100, 40, 80);
  const std::vector<Supervoxel> frame = Supervoxels(
      scene, {{40, 60, 40, 80}, {60, 80, 40, 80}, {80, 100, 40, 80}}, {{1}, {0, 2}, {1}});
  for (std::uint32_t target = 0; target < frame.size(); ++target) {
    const ChangeEvidence e = Detect(scene, scene, frame, target);
    EXPECT_EQ(e.object_supported_points, 2400u);
    EXPECT_FALSE(e.moved);
  }
}

}  // namespace
}  // namespace relmap::perception
