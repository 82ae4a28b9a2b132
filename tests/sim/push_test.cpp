// The push primitive: a push moves a free ball, never a static body, reports
// the body it aimed at, and is refused when no approach is free.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <thread>

#include "world_test_scenes.h"

namespace relmap::sim {
namespace {

using ::testing::Contains;
using testing::LoadOrDie;
using ::testing::Not;

// Body 0: a table whose top is the plane z = 0. Body 1: a static block, a 10 cm
// cube at (0.3, 0, 0.05). Body 2: a ball of radius 3 cm resting at the origin.
// The camera looks down at 45 degrees from 0.7 m.
constexpr char kTableBlockBall[] = R"({"name": "TableBlockBall",
  "camera": {"position": {"x": -0.5, "z": 0.5}, "look_at": {}},
  "static_bodies": [
    {"name": "table", "shape": "box", "size": {"x": 1.5, "y": 1.5, "z": 0.05},
     "color": {"r": 200}, "pose": {"position": {"z": -0.025}}},
    {"name": "block", "shape": "box", "size": {"x": 0.1, "y": 0.1, "z": 0.1},
     "color": {"g": 200}, "pose": {"position": {"x": 0.3, "z": 0.05}}}],
  "objects": [
    {"name": "ball", "shape": "sphere", "radius": 0.03, "color": {"b": 200}, "mass": 0.08,
     "spawn": {"min": {"z": 0.0302}, "max": {"z": 0.0302}, "orientation": "fixed"}}]})";
constexpr std::int32_t kTable = 0, kBlock = 1, kBall = 2;

Eigen::Vector3f InCamera(const OdeScene& scene, const Eigen::Vector3d& world) {
  return scene.WorldToCamera(world).cast<float>();
}

TEST(Push, TheBallRestsWhereItWasSpawned) {
  auto scene = LoadOrDie(kTableBlockBall);
  EXPECT_TRUE(scene->AtRest());
  EXPECT_NEAR(scene->BodyPose(kBall).translation().x(), 0.0, 1e-4);
  EXPECT_NEAR(scene->BodyPose(kBall).translation().z(), 0.03, 5e-4);
}

TEST(Push, APushAtAFreeBallMovesIt) {
  auto scene = LoadOrDie(kTableBlockBall);
  const Eigen::Vector3d before = scene->BodyPose(kBall).translation();
  // The ball's top, as a supervoxel on it would be seen.
  const PushReport report = scene->Push(InCamera(*scene, before + Eigen::Vector3d(0, 0, 0.02)), 3);
  EXPECT_TRUE(report.executed);
  EXPECT_EQ(report.target_body, kBall);
  EXPECT_THAT(report.moved_bodies, Contains(kBall));
  EXPECT_GT((scene->BodyPose(kBall).translation() - before).norm(), 0.01);
  EXPECT_GT(report.simulated_seconds, 0.5);  // 8 cm there and back at 0.15 m/s, then settling
  EXPECT_TRUE(scene->AtRest());
}

TEST(Push, ReportsAPlainBallsMotionWithoutTheTurnNoCameraSees) {
  // The ball rolls: its body turns, but a plain sphere looks the same turned about its
  // centre, so the reported motion is its centre's translation (visible_motion.h).
  auto scene = LoadOrDie(kTableBlockBall);
  const Eigen::Vector3d before = scene->BodyPose(kBall).translation();
  const Eigen::Matrix3d turn_before = scene->BodyPose(kBall).linear();
  const PushReport report = scene->Push(InCamera(*scene, before + Eigen::Vector3d(0, 0, 0.02)), 3);
  ASSERT_TRUE(report.executed);
  const Eigen::Matrix3d turned = scene->BodyPose(kBall).linear() * turn_before.transpose();
  EXPECT_GT(Eigen::AngleAxisd(turned).angle(), 0.1);  // it rolled
  const Eigen::Isometry3f& seen = report.body_motions[kBall];
  EXPECT_TRUE(seen.linear().isApprox(Eigen::Matrix3f::Identity(), 1e-5f));
  const Eigen::Vector3f centre = InCamera(*scene, before);
  const Eigen::Vector3f moved = InCamera(*scene, scene->BodyPose(kBall).translation());
  EXPECT_TRUE((seen * centre).isApprox(moved, 1e-4f));
}

TEST(Push, PushesFromEverySeedMoveTheBall) {
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    auto scene = LoadOrDie(kTableBlockBall);
    const PushReport report =
        scene->Push(InCamera(*scene, scene->BodyPose(kBall).translation()), seed);
    EXPECT_TRUE(report.executed) << seed;
    EXPECT_THAT(report.moved_bodies, Contains(kBall)) << seed;
  }
}

TEST(Push, APushAtAStaticBodyMovesNothing) {
  auto scene = LoadOrDie(kTableBlockBall);
  const Eigen::Vector3d ball = scene->BodyPose(kBall).translation();
  // The block's front face, at mid height (a supervoxel on it).
  const PushReport report = scene->Push(InCamera(*scene, Eigen::Vector3d(0.25, 0, 0.05)), 5);
  EXPECT_EQ(report.target_body, kBlock);
  EXPECT_THAT(report.moved_bodies, Not(Contains(kBlock)));
  EXPECT_THAT(report.moved_bodies, Not(Contains(kTable)));
  EXPECT_EQ(scene->BodyPose(kBlock).translation(), Eigen::Vector3d(0.3, 0, 0.05));
  EXPECT_LT((scene->BodyPose(kBall).translation() - ball).norm(), 0.01);
}

TEST(Push, APushAtAFixedSpheresFlankMovesNothing) {
  // MoveableBricks2's fixed spheres: the pusher goes into the flank (it is not
  // lifted over the sphere as it is lifted above a table).
  auto scene = LoadOrDie(R"({"name": "FixedSphere",
    "camera": {"position": {"x": -0.5, "z": 0.5}, "look_at": {}},
    "static_bodies": [
      {"shape": "box", "size": {"x": 1.5, "y": 1.5, "z": 0.05}, "color": {"r": 200},
       "pose": {"position": {"z": -0.025}}},
      {"shape": "sphere", "radius": 0.035, "color": {"r": 200},
       "pose": {"position": {"z": 0.035}}}],
    "objects": [
      {"shape": "box", "size": {"x": 0.04, "y": 0.04, "z": 0.04}, "color": {"b": 200},
       "mass": 0.1, "spawn": {"min": {"x": 0.4, "z": 0.021}, "max": {"x": 0.4, "z": 0.021}}}]})");
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    const PushReport report = scene->Push(InCamera(*scene, Eigen::Vector3d(-0.03, 0, 0.05)), seed);
    EXPECT_EQ(report.target_body, 1) << seed;
    EXPECT_TRUE(report.moved_bodies.empty()) << seed;
  }
}

TEST(Push, APushAtTheTableMovesNothing) {
  auto scene = LoadOrDie(kTableBlockBall);
  const PushReport report = scene->Push(InCamera(*scene, Eigen::Vector3d(-0.3, 0.3, 0)), 1);
  EXPECT_TRUE(report.executed);
  EXPECT_EQ(report.target_body, kTable);
  EXPECT_TRUE(report.moved_bodies.empty());
}

TEST(Push, IsNotExecutedWhenEveryApproachIsBlocked) {
  auto scene = LoadOrDie(kTableBlockBall);
  // Deep inside the table: every start pose 6 cm away is inside it too.
  const PushReport report = scene->Push(InCamera(*scene, Eigen::Vector3d(0, 0.4, -0.025)), 1);
  EXPECT_FALSE(report.executed);
  EXPECT_EQ(report.target_body, kTable);
  EXPECT_TRUE(report.moved_bodies.empty());
  EXPECT_EQ(report.simulated_seconds, 0);
}

TEST(Push, IsDeterministicPerSeed) {
  auto a = LoadOrDie(kTableBlockBall);
  auto b = LoadOrDie(kTableBlockBall);
  const Eigen::Vector3f target = InCamera(*a, a->BodyPose(kBall).translation());
  a->Push(target, 11);
  b->Push(target, 11);
  EXPECT_TRUE(a->BodyPose(kBall).isApprox(b->BodyPose(kBall), 1e-12));
}

TEST(Push, ThePusherNeverShowsInTheCamera) {
  auto scene = LoadOrDie(kTableBlockBall);
  scene->Push(InCamera(*scene, scene->BodyPose(kBall).translation()), 2);
  for (const std::int32_t id : scene->Capture().body_ids) {
    EXPECT_TRUE(id == kNoBody || (id >= 0 && id < scene->body_count()));
  }
}

TEST(Push, ScenesOnDifferentThreadsDoNotDisturbEachOther) {
  // Each scene owns its ODE world, space and step threading: two threads pushing
  // their own copies end where one thread alone ends.
  const auto run = [] {
    auto scene = LoadOrDie(kTableBlockBall);
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
      scene->Push(InCamera(*scene, scene->BodyPose(kBall).translation()), seed);
      scene->Capture();
    }
    return scene->BodyPose(kBall);
  };
  const Eigen::Isometry3d alone = run();
  Eigen::Isometry3d a, b;
  std::thread first([&] { a = run(); });
  std::thread second([&] { b = run(); });
  first.join();
  second.join();
  EXPECT_TRUE(a.isApprox(alone, 1e-12));
  EXPECT_TRUE(b.isApprox(alone, 1e-12));
}

}  // namespace
}  // namespace relmap::sim
