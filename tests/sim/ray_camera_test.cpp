// The ideal ray-cast camera against analytic geometry: depths, the camera
// frame's axes, ground-truth ids, holes and depth noise.
#include <gtest/gtest.h>

#include <cmath>

#include "frame_pixels.h"
#include "world_test_scenes.h"

namespace relmap::sim {
namespace {

using testing::kAxisCamera;
using testing::LoadOrDie;

// Body 0: a box whose front face is the plane x = 1 (|y|, |z| <= 0.2).
// Body 1: a wall whose front face is the plane x = 2.95.
// Body 2: a moveable ball of radius 0.1 at (1.5, 0.6, 0), held there by zero gravity.
std::string BoxWallBall() {
  return std::string(R"({"name": "BoxWallBall", )") + kAxisCamera + R"(,
    "static_bodies": [
      {"shape": "box", "size": {"x": 0.2, "y": 0.4, "z": 0.4}, "color": {"r": 255},
       "pose": {"position": {"x": 1.1}}},
      {"shape": "box", "size": {"x": 0.1, "y": 8, "z": 8}, "color": {"g": 255},
       "pose": {"position": {"x": 3}}}],
    "objects": [
      {"shape": "sphere", "radius": 0.1, "color": {"b": 255}, "mass": 0.1,
       "spawn": {"min": {"x": 1.5, "y": 0.6}, "max": {"x": 1.5, "y": 0.6},
                 "orientation": "fixed"}}],
    "physics": {"gravity": 0}})";
}

TEST(RayCamera, FramesAreOrganizedAtTheCamerasSize) {
  auto scene = LoadOrDie(BoxWallBall());
  const CameraFrame frame = scene->Capture();
  EXPECT_EQ(frame.width, 65u);
  EXPECT_EQ(frame.height, 49u);
  EXPECT_EQ(frame.points.size(), 65u * 49u);
  EXPECT_EQ(frame.body_ids.size(), 65u * 49u);
}

TEST(RayCamera, TheOpticalAxisHitsTheBoxFaceAtItsDistance) {
  auto scene = LoadOrDie(BoxWallBall());
  const CameraFrame frame = scene->Capture();
  const CameraPoint& p = At(frame, 32, 24);
  EXPECT_NEAR(p.x, 0.0, 1e-6);
  EXPECT_NEAR(p.y, 0.0, 1e-6);
  EXPECT_NEAR(p.z, 1.0, 1e-6);
}

TEST(RayCamera, OffAxisPixelsHitTheFacePlaneWhereThePinholeModelSays) {
  auto scene = LoadOrDie(BoxWallBall());
  const CameraFrame frame = scene->Capture();
  // Pixel (u, v) meets the plane z = 1 (camera frame) at ((u-32)/50, (v-24)/50, 1):
  // x right and y down, as a Kinect's clouds.
  for (const auto& [u, v] : {std::pair{40, 24}, {32, 30}, {25, 18}, {41, 33}}) {
    const CameraPoint& p = At(frame, u, v);
    EXPECT_NEAR(p.x, (u - 32) / 50.0, 1e-5) << u << "," << v;
    EXPECT_NEAR(p.y, (v - 24) / 50.0, 1e-5) << u << "," << v;
    EXPECT_NEAR(p.z, 1.0, 1e-5) << u << "," << v;
  }
}

TEST(RayCamera, ASphereIsHitAtItsAnalyticDistance) {
  auto scene = LoadOrDie(BoxWallBall());
  const CameraFrame frame = scene->Capture();
  // The ball's centre (1.5, 0.6, 0) in the camera frame is c = (-0.6, 0, 1.5): pixel
  // u = 32 + 50 * (-0.6 / 1.5) = 12. Along the unit ray d: t = d.c - sqrt((d.c)^2 - |c|^2 + r^2).
  for (const int u : {12, 10, 14}) {
    const Eigen::Vector3d d = Eigen::Vector3d((u - 32) / 50.0, 0, 1).normalized();
    const Eigen::Vector3d c(-0.6, 0, 1.5);
    const double dc = d.dot(c);
    const double t = dc - std::sqrt(dc * dc - c.squaredNorm() + 0.1 * 0.1);
    const CameraPoint& p = At(frame, u, 24);
    EXPECT_NEAR(Eigen::Vector3d(p.x, p.y, p.z).norm(), t, 1e-5) << u;
    EXPECT_NEAR(p.x, t * d.x(), 1e-5);
    EXPECT_NEAR(p.z, t * d.z(), 1e-5);
  }
}

TEST(RayCamera, EveryPixelCarriesTheIdOfTheBodyItsRayHit) {
  auto scene = LoadOrDie(BoxWallBall());
  const CameraFrame frame = scene->Capture();
  EXPECT_EQ(IdAt(frame, 32, 24), 0);  // the box's image centre
  EXPECT_EQ(IdAt(frame, 12, 24), 2);  // the ball's
  EXPECT_EQ(IdAt(frame, 0, 0), 1);    // off both: the wall behind
  EXPECT_EQ(IdAt(frame, 64, 48), 1);
  EXPECT_FALSE(scene->IsMoveable(0));
  EXPECT_FALSE(scene->IsMoveable(1));
  EXPECT_TRUE(scene->IsMoveable(2));
  EXPECT_FALSE(scene->IsMoveable(kNoBody));
  EXPECT_FALSE(scene->IsMoveable(3));
}

TEST(RayCamera, TheNearestOfSeveralHitsWins) {
  // The wall lies behind the box on the optical axis: the box (depth 1) must win
  // over the wall (2.95) whatever order the space reports them in.
  auto scene = LoadOrDie(BoxWallBall());
  const CameraFrame frame = scene->Capture();
  for (int u = 23; u <= 41; ++u) {
    EXPECT_EQ(IdAt(frame, u, 24), 0) << u;
    EXPECT_NEAR(At(frame, u, 24).z, 1.0, 1e-5) << u;
  }
}

TEST(RayCamera, ColoursComeFromTheHitBody) {
  auto scene = LoadOrDie(BoxWallBall());
  const CameraFrame frame = scene->Capture();
  const CameraPoint& box = At(frame, 32, 24);
  EXPECT_GT(box.r, 0);
  EXPECT_EQ(box.g, 0);
  EXPECT_EQ(box.b, 0);
  const CameraPoint& wall = At(frame, 0, 0);
  EXPECT_EQ(wall.r, 0);
  EXPECT_GT(wall.g, 0);
}

// A wall whose front face is the plane x = `wall_x` - 0.05 (body 0) and a small
// ball out of sight behind the camera (body 1), seen by `camera`.
std::string WallScene(const std::string& camera, double wall_x) {
  return R"({"name": "Wall", "camera": )" + camera + R"(,
    "static_bodies": [{"shape": "box", "size": {"x": 0.1, "y": 8, "z": 8},
      "color": {"g": 255}, "pose": {"position": {"x": )" +
         std::to_string(wall_x) + R"(}}}],
    "objects": [{"shape": "sphere", "radius": 0.01, "color": {"b": 255}, "mass": 0.1,
      "spawn": {"min": {"x": -5}, "max": {"x": -5}}}],
    "physics": {"gravity": 0}})";
}

TEST(RayCamera, RaysBeyondTheMaximumRangeAreHoles) {
  auto scene =
      LoadOrDie(WallScene(R"({"sensor": "ideal", "position": {}, "look_at": {"x": 1}, "width": 65,
      "height": 49, "fx": 50, "max_range": 2.0})",
                          3.0));
  const CameraFrame frame = scene->Capture();
  for (const CameraPoint& hole : frame.points) {
    EXPECT_TRUE(std::isnan(hole.x) && std::isnan(hole.y) && std::isnan(hole.z));
  }
  for (const std::int32_t id : frame.body_ids) EXPECT_EQ(id, kNoBody);
}

TEST(RayCamera, DepthNoiseIsGaussianAlongTheRayAndSeeded) {
  const std::string noisy =
      WallScene(R"({"sensor": "ideal", "position": {}, "look_at": {"x": 1}, "width": 65,
      "height": 49, "fx": 50, "depth_noise_sigma": 0.01})",
                1.05);
  auto a = LoadOrDie(noisy, 7);
  auto b = LoadOrDie(noisy, 7);
  const CameraFrame fa = a->Capture();
  const CameraFrame fb = b->Capture();
  double sum = 0, sum_sq = 0;
  for (std::size_t i = 0; i < fa.points.size(); ++i) {
    EXPECT_EQ(fa.points[i].z, fb.points[i].z);  // same seed, same noise
    const CameraPoint& p = fa.points[i];
    // The wall's face is the plane z = 1 in the camera frame: the noise-free
    // distance along the ray through p is |p| / p.z.
    const double along = Eigen::Vector3d(p.x, p.y, p.z).norm();
    const double error = along - along / p.z;
    sum += error;
    sum_sq += error * error;
  }
  const auto n = static_cast<double>(fa.points.size());
  EXPECT_NEAR(sum / n, 0.0, 0.001);
  EXPECT_NEAR(std::sqrt(sum_sq / n), 0.01, 0.001);
  EXPECT_NE(a->Capture().points[0].z, fa.points[0].z);  // the next frame draws anew
}

TEST(RayCamera, ATriangleMeshIsHitAtItsFace) {
  // A static square (two triangles) in the plane x = 2, facing the camera.
  auto scene = LoadOrDie(std::string(R"({"name": "Mesh", )") + kAxisCamera + R"(,
    "static_bodies": [{"shape": "mesh", "color": {"r": 255},
      "mesh": {"vertices": [2, -1, -1, 2, 1, -1, 2, 1, 1, 2, -1, 1],
               "indices": [0, 2, 1, 0, 3, 2]}}],
    "objects": [{"shape": "sphere", "radius": 0.01, "color": {"b": 255}, "mass": 0.1,
      "spawn": {"min": {"x": -5}, "max": {"x": -5}}}],
    "physics": {"gravity": 0}})");
  const CameraFrame frame = scene->Capture();
  const CameraPoint& p = At(frame, 40, 30);
  EXPECT_EQ(IdAt(frame, 40, 30), 0);
  EXPECT_NEAR(p.z, 2.0, 1e-5);
  EXPECT_NEAR(p.x, 2.0 * 8 / 50.0, 1e-5);
}

TEST(RayCamera, ResizingKeepsTheFieldOfView) {
  auto scene = LoadOrDie(BoxWallBall());
  scene->SetImageSize(130, 98);
  const CameraFrame frame = scene->Capture();
  EXPECT_EQ(frame.width, 130u);
  // The box's face edge |x| = 0.2 at depth 1 stays at the same fraction of the width.
  EXPECT_NEAR(scene->camera().fx, 100.0, 1e-9);
  EXPECT_NEAR(scene->camera().cx, 64.5, 1e-9);
}

}  // namespace
}  // namespace relmap::sim
