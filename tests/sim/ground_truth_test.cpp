// A supervoxel is an object when at least half of its points hit a moveable body
// (docs/method.md §6), its points named by the server's point labels; a push moved it when
// at least half of its points moved with their bodies by more than the motion threshold.
#include "ground_truth.h"

#include <gtest/gtest.h>

namespace relmap::sim {
namespace {

// Bodies 1 and 2 are moveable, 0 (the table) and 3 are not.
bool Moveable(std::int32_t body) { return body == 1 || body == 2; }

// A 4×2 frame: the body behind every point and the supervoxel the server put it in.
struct Frame {
  CameraFrame frame;
  v1::ComputeMapsResponse maps;
};

Frame MakeFrame(const std::vector<std::int32_t>& bodies, const std::vector<int>& labels,
                int supervoxels) {
  Frame f;
  f.frame.width = 4;
  f.frame.height = 2;
  f.frame.points.resize(8);
  f.frame.body_ids = bodies;
  for (const int label : labels) f.maps.add_point_labels(label);
  for (int id = 0; id < supervoxels; ++id)
    f.maps.add_supervoxels()->set_id(static_cast<unsigned>(id));
  return f;
}

TEST(SupervoxelGroundTruth, HalfOfThePointsOnMoveableBodiesMakeAnObject) {
  // Supervoxel 0: bodies 1, 1, 0 → 2/3 moveable → object.
  // Supervoxel 1: bodies 2, 3 → 1/2 moveable → object (the bound is inclusive).
  // Supervoxel 2: bodies 0, 3 and an unsegmented point of body 1 → 0/2 → background.
  const Frame f = MakeFrame({1, 1, 0, 2, 3, 0, 3, 1}, {0, 0, 0, 1, 1, 2, 2, -1}, 3);
  const StatusOr<std::vector<bool>> object = SupervoxelGroundTruth(f.frame, f.maps, Moveable);
  ASSERT_TRUE(object.ok()) << object.status().message();
  EXPECT_EQ(*object, (std::vector<bool>{true, true, false}));
}

TEST(SupervoxelGroundTruth, HolesCountForNoBody) {
  // Supervoxel 0: a hole (no body) and body 2 → 1/2 → object; supervoxel 1: a hole
  // and three table points → 0/4 → background.
  const Frame f = MakeFrame({kNoBody, 2, kNoBody, 0, 0, 0, 3, 3}, {0, 0, 1, 1, 1, 1, -1, -1}, 2);
  EXPECT_EQ(*SupervoxelGroundTruth(f.frame, f.maps, Moveable), (std::vector<bool>{true, false}));
}

TEST(SupervoxelGroundTruth, FollowsTheOrderOfTheMapsNotTheIds) {
  // The maps list supervoxel 1 before supervoxel 0.
  Frame f = MakeFrame({1, 1, 1, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 1, 1, 1}, 0);
  f.maps.add_supervoxels()->set_id(1);
  f.maps.add_supervoxels()->set_id(0);
  EXPECT_EQ(*SupervoxelGroundTruth(f.frame, f.maps, Moveable), (std::vector<bool>{false, true}));
}

TEST(SupervoxelGroundTruth, MapsWithoutPointLabelsAreRejected) {
  Frame f = MakeFrame({1, 1, 1, 1, 0, 0, 0, 0}, {}, 2);
  EXPECT_EQ(SupervoxelGroundTruth(f.frame, f.maps, Moveable).status().code(),
            StatusCode::kInvalidArgument);
}

TEST(SupervoxelGroundTruth, ALabelTheMapsDoNotListIsRejected) {
  Frame f = MakeFrame({1, 1, 1, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 5, 1, 1, 1}, 2);
  EXPECT_EQ(SupervoxelGroundTruth(f.frame, f.maps, Moveable).status().code(),
            StatusCode::kInvalidArgument);
}

// Points 0-3 along x at z = 1 m, 10 cm apart (x = -0.15, -0.05, 0.05, 0.15); 4-7 further.
Frame LinedUp(const std::vector<std::int32_t>& bodies, const std::vector<int>& labels) {
  Frame f = MakeFrame(bodies, labels, 2);
  for (int p = 0; p < 8; ++p) {
    f.frame.points[static_cast<std::size_t>(p)] = {-0.15f + 0.1f * static_cast<float>(p), 0, 1};
  }
  return f;
}

PushReport Moves(std::int32_t body, const Eigen::Isometry3f& motion) {
  PushReport push;
  push.executed = true;
  push.motion_threshold = 0.01;
  push.body_motions.assign(4, Eigen::Isometry3f::Identity());
  push.body_motions[static_cast<std::size_t>(body)] = motion;
  return push;
}

TEST(DisplacementOf, AnObjectTurnedAboutItsCentreMoved) {
  // Body 1 turns 10° about the vertical (y) axis through (0, 0, 1): its centre stays, the
  // points 5 cm from it move 2 r sin 5° = 0.87 cm (within 1 cm), those 15 cm from it
  // 2.6 cm: 2 of 4 displaced, half, so it moved (the bound is inclusive).
  const Frame f = LinedUp({1, 1, 1, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 1, 1, 1});
  const Eigen::Vector3f centre(0, 0, 1);
  const Eigen::Isometry3f turn =
      Eigen::Translation3f(centre) *
      Eigen::AngleAxisf(10.0f * 3.14159265f / 180, Eigen::Vector3f::UnitY()) *
      Eigen::Translation3f(-centre);
  const StatusOr<SupervoxelDisplacement> d = DisplacementOf(f.frame, f.maps, 0, Moves(1, turn));
  ASSERT_TRUE(d.ok()) << d.status().message();
  EXPECT_EQ(d->points, 4u);
  EXPECT_EQ(d->displaced, 2u);
  EXPECT_TRUE(d->moved());
}

TEST(DisplacementOf, ASupervoxelIsJudgedByMostOfItsPoints) {
  // Supervoxel 0 is three points of body 2, which stays, and one of body 1, which moves
  // 5 cm: 1 of 4 displaced, not moved. Supervoxel 1 (points of the table) did not move.
  const Frame f = LinedUp({2, 2, 2, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 1, 1, 1});
  const PushReport push = Moves(1, Eigen::Isometry3f(Eigen::Translation3f(0.05f, 0, 0)));
  const StatusOr<SupervoxelDisplacement> mixed = DisplacementOf(f.frame, f.maps, 0, push);
  ASSERT_TRUE(mixed.ok());
  EXPECT_EQ(mixed->displaced, 1u);
  EXPECT_DOUBLE_EQ(mixed->share(), 0.25);
  EXPECT_FALSE(mixed->moved());
  EXPECT_FALSE(DisplacementOf(f.frame, f.maps, 1, push)->moved());
}

TEST(DisplacementOf, ATranslationAtTheThresholdIsNotAMove) {
  // 9 mm is within the 1 cm threshold; 11 mm is beyond it.
  const Frame f = LinedUp({1, 1, 1, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 1, 1, 1});
  EXPECT_FALSE(DisplacementOf(f.frame, f.maps, 0,
                              Moves(1, Eigen::Isometry3f(Eigen::Translation3f(0, 0, 0.009f))))
                   ->moved());
  EXPECT_TRUE(DisplacementOf(f.frame, f.maps, 0,
                             Moves(1, Eigen::Isometry3f(Eigen::Translation3f(0, 0, 0.011f))))
                  ->moved());
}

TEST(DisplacementOf, AHoleIsNeverDisplaced) {
  const Frame f = LinedUp({kNoBody, kNoBody, kNoBody, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 1, 1, 1});
  const auto d = DisplacementOf(f.frame, f.maps, 0,
                                Moves(1, Eigen::Isometry3f(Eigen::Translation3f(0.05f, 0, 0))));
  EXPECT_EQ(d->displaced, 1u);
  EXPECT_FALSE(d->moved());
}

TEST(DisplacementOf, ABodyThePushSaysNothingOfIsRejected) {
  const Frame f = LinedUp({1, 1, 1, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 1, 1, 1});
  EXPECT_EQ(DisplacementOf(f.frame, f.maps, 0, PushReport{}).status().code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::sim
