// The camera's intrinsics read back from an organized cloud, and a known camera motion
// recovered by the registration that the change detector runs first.
#include "perception/camera_motion.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "perception/synthetic_tabletop.h"
#include "test_data.h"

namespace relmap::perception {
namespace {

TEST(CameraMotion, ReadsThePinholeOfAnOrganizedCloud) {
  for (const std::uint32_t width : {640u, 320u}) {
    SyntheticTabletopOptions options;
    options.width = width;
    options.height = width * 3 / 4;
    const SyntheticTabletop scene = MakeSyntheticTabletop(options);
    const std::optional<Intrinsics> k = IntrinsicsOf(scene.cloud);
    ASSERT_TRUE(k.has_value()) << width;
    const double f = 525.0 * width / 640.0;
    EXPECT_NEAR(k->fx, f, 1e-3 * f);
    EXPECT_NEAR(k->fy, f, 1e-3 * f);
    EXPECT_NEAR(k->cx, (width - 1) / 2.0, 0.05);
    EXPECT_NEAR(k->cy, (options.height - 1) / 2.0, 0.05);
  }
}

TEST(CameraMotion, FindsNoPinholeInAnUnorganizedCloud) {
  const SyntheticTabletop scene = MakeSyntheticTabletop();
  std::vector<CloudPoint> points = scene.cloud.points();
  StatusOr<Cloud> flat = MakeCloud(static_cast<std::uint32_t>(points.size()), 1, points);
  ASSERT_TRUE(flat.ok());
  EXPECT_FALSE(IntrinsicsOf(*flat).has_value());
}

// A real Kinect frame seen from a camera turned by 1 degree and moved by 1 cm: its points
// moved by the inverse motion, re-projected into its own pixels.
TEST(CameraMotion, RecoversAKnownMotionOfARealFrame) {
  RELMAP_LOAD_REAL_CLOUD(before, "kinect_static_seq_1.pcd");
  const std::optional<Intrinsics> k = IntrinsicsOf(before);
  ASSERT_TRUE(k.has_value());
  Eigen::Isometry3f before_from_after = Eigen::Isometry3f::Identity();
  before_from_after.linear() =
      Eigen::AngleAxisf(1.0f * 3.14159265f / 180.0f, Eigen::Vector3f(0.3f, 1.0f, 0.2f).normalized())
          .toRotationMatrix();
  before_from_after.translation() = Eigen::Vector3f(0.006f, -0.005f, 0.006f);
  const std::vector<SeenPoint> seen =
      ReprojectInto(before, before_from_after.inverse(), *k, before.width(), before.height());
  std::vector<CloudPoint> points(seen.size());
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const Eigen::Vector3f& q = seen[i].position;
    points[i].x = q.x(), points[i].y = q.y(), points[i].z = q.z();
  }
  StatusOr<Cloud> after = MakeCloud(before.width(), before.height(), points);
  ASSERT_TRUE(after.ok());

  const CameraMotion motion = EstimateCameraMotion(before, *after, 5000, 0.05f);
  ASSERT_TRUE(motion.converged);
  EXPECT_NEAR(motion.rotation_deg, 1.0, 0.05);
  EXPECT_NEAR(motion.translation_m, before_from_after.translation().norm(), 0.001);
  const Eigen::Isometry3f error = motion.before_from_after * before_from_after.inverse();
  EXPECT_LT(Eigen::AngleAxisf(error.linear()).angle() * 180.0 / 3.14159265, 0.05);
  EXPECT_LT(error.translation().norm(), 0.001f);
}

}  // namespace
}  // namespace relmap::perception
