// The test double itself: its camera, its ground truth, its re-spawns and pushes, so
// that the runner's tests stand on a world that behaves as SimulatedScene promises.
#include "sim/analytic_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace relmap::sim::testing {
namespace {

TEST(AnalyticScene, EveryTablePointLiesOneMetreAway) {
  AnalyticScene scene(1, 161, 121);
  const CameraFrame frame = scene.Capture();
  ASSERT_EQ(frame.points.size(), 161u * 121u);
  ASSERT_EQ(frame.body_ids.size(), frame.points.size());
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    if (frame.body_ids[i] != AnalyticScene::kTable) continue;
    const CameraPoint& p = frame.points[i];
    EXPECT_FLOAT_EQ(p.z, AnalyticScene::kTableDepth) << i;
  }
}

TEST(AnalyticScene, ARayThroughABallsCentreStopsAtItsNearSide) {
  AnalyticScene scene(3);
  const Eigen::Vector3f c = scene.centre(AnalyticScene::kBlueBall);
  // The ball rests on the table: its centre 6 cm in front of it.
  EXPECT_FLOAT_EQ(c.z(), AnalyticScene::kTableDepth - 0.06f);
  // The pixel whose ray passes nearest the centre.
  const CameraFrame frame = scene.Capture();
  std::size_t best = 0;
  float closest = INFINITY;
  for (std::uint32_t v = 0; v < frame.height; ++v) {
    for (std::uint32_t u = 0; u < frame.width; ++u) {
      const Eigen::Vector3f d = scene.Ray(u, v).normalized();
      const float miss = (c - c.dot(d) * d).norm();
      if (miss < closest) closest = miss, best = static_cast<std::size_t>(v) * frame.width + u;
    }
  }
  EXPECT_EQ(frame.body_ids[best], AnalyticScene::kBlueBall);
  const CameraPoint& p = frame.points[best];
  // Along that ray the near surface lies at |c|·cos − sqrt(r² − miss²) from the camera.
  const float range = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  const float expected =
      std::sqrt(c.squaredNorm() - closest * closest) - std::sqrt(0.06f * 0.06f - closest * closest);
  EXPECT_NEAR(range, expected, 1e-5f);
}

TEST(AnalyticScene, OnlyTheBallsAndTheBrickAreMoveable) {
  AnalyticScene scene(1);
  EXPECT_FALSE(scene.IsMoveable(AnalyticScene::kTable));
  EXPECT_TRUE(scene.IsMoveable(AnalyticScene::kBlueBall));
  EXPECT_TRUE(scene.IsMoveable(AnalyticScene::kGreenBall));
  EXPECT_TRUE(scene.IsMoveable(AnalyticScene::kYellowBrick));
  EXPECT_FALSE(scene.IsMoveable(AnalyticScene::kFixedRedBlock));
  EXPECT_FALSE(scene.IsMoveable(kNoBody));
}

TEST(AnalyticScene, EveryBodyIsInViewAndTheBorderIsAHole) {
  AnalyticScene scene(5);
  const CameraFrame frame = scene.Capture();
  EXPECT_EQ(std::set<std::int32_t>(frame.body_ids.begin(), frame.body_ids.end()),
            (std::set<std::int32_t>{kNoBody, 0, 1, 2, 3, 4}));
  EXPECT_EQ(frame.body_ids[0], kNoBody);  // the table ends before the picture does
  EXPECT_TRUE(std::isnan(frame.points[0].x));
}

TEST(AnalyticScene, RespawnIsAFunctionOfItsSeedAndMovesOnlyMoveableBodies) {
  AnalyticScene a(1), b(2);
  a.Respawn(42);
  b.Respawn(42);
  for (std::int32_t id = 0; id <= AnalyticScene::kFixedRedBlock; ++id) {
    EXPECT_EQ(a.centre(id), b.centre(id)) << id;
  }
  const Eigen::Vector3f block = a.centre(AnalyticScene::kFixedRedBlock);
  const Eigen::Vector3f ball = a.centre(AnalyticScene::kBlueBall);
  a.Respawn(43);
  EXPECT_EQ(a.centre(AnalyticScene::kFixedRedBlock), block);
  EXPECT_NE(a.centre(AnalyticScene::kBlueBall), ball);
}

TEST(AnalyticScene, APushMovesTheBallItTouchesAndNeverTheFixedBlock) {
  AnalyticScene scene(1);
  const Eigen::Vector3f ball = scene.centre(AnalyticScene::kGreenBall);
  const PushReport pushed = scene.Push(ball - Eigen::Vector3f(0, 0, 0.05f), 9);  // its top
  EXPECT_TRUE(pushed.executed);
  EXPECT_EQ(pushed.target_body, AnalyticScene::kGreenBall);
  EXPECT_EQ(pushed.moved_bodies, (std::vector<std::int32_t>{AnalyticScene::kGreenBall}));
  EXPECT_NEAR((scene.centre(AnalyticScene::kGreenBall) - ball).norm(), AnalyticScene::kPushDistance,
              1e-6f);

  const Eigen::Vector3f block = scene.centre(AnalyticScene::kFixedRedBlock);
  const PushReport blocked = scene.Push(block - Eigen::Vector3f(0, 0, 0.04f), 9);
  EXPECT_EQ(blocked.target_body, AnalyticScene::kFixedRedBlock);
  EXPECT_TRUE(blocked.moved_bodies.empty());
  EXPECT_EQ(scene.centre(AnalyticScene::kFixedRedBlock), block);
}

}  // namespace
}  // namespace relmap::sim::testing
