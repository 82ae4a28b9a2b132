// The simulator's packed clouds against the server's decoder: a camera frame packed for
// the API (sim_backend/packed_cloud.h) decodes, with the decoder the server runs, to the
// same points. The two sides' layouts are tested on their own in tests/sim and
// tests/perception; this is the contract between them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "packed_cloud.h"
#include "perception/decode.h"
#include "sim/three_point_frame.h"

namespace relmap::sim {
namespace {

TEST(PackCloud, RoundTripsThroughTheServersDecoder) {
  const CameraFrame frame = ThreePoints();
  const v1::Cloud packed = PackCloud(frame);
  const StatusOr<perception::Cloud> cloud = perception::DecodePacked(
      packed.packed().points(), packed.packed().width(), packed.packed().height());
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  ASSERT_EQ(cloud->size(), 3u);
  EXPECT_EQ(cloud->valid_points(), 2u);
  for (const std::size_t i : {0u, 2u}) {
    const perception::CloudPoint p = cloud->point(i);
    const CameraPoint& q = frame.points[i];
    EXPECT_EQ(p.x, q.x);
    EXPECT_EQ(p.y, q.y);
    EXPECT_EQ(p.z, q.z);
    EXPECT_EQ(p.r, q.r);
    EXPECT_EQ(p.g, q.g);
    EXPECT_EQ(p.b, q.b);
    EXPECT_EQ(p.a, 255);
  }
  const perception::CloudPoint hole = cloud->point(1);
  EXPECT_TRUE(std::isnan(hole.x) && std::isnan(hole.y) && std::isnan(hole.z));
}

}  // namespace
}  // namespace relmap::sim
