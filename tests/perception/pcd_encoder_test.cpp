// EncodePcd writes what DecodePcd (and so the server) reads back, point for point.
#include "common/pcd/pcd_encoder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "perception/decode.h"

namespace relmap::perception {
namespace {

TEST(PcdEncoder, AnOrganizedCloudDecodesBackExactlyWithItsHoles) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<CloudPoint> points = {{0.1f, 0.2f, 1.0f, 255, 0, 0, 255},
                                          {nan, nan, nan, 0, 0, 0, 255},
                                          {-0.3f, 0.25f, 1.5f, 10, 200, 30, 255},
                                          {0.0f, -0.1f, 0.8f, 1, 2, 3, 255}};
  const StatusOr<Cloud> cloud = DecodePcd(pcd::EncodePcd(2, 2, points));
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  EXPECT_EQ(cloud->width(), 2u);
  EXPECT_EQ(cloud->height(), 2u);
  EXPECT_EQ(cloud->valid_points(), 3u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CloudPoint p = cloud->point(i);
    if (i == 1) {
      EXPECT_TRUE(std::isnan(p.x));
      continue;
    }
    EXPECT_EQ(p.x, points[i].x);
    EXPECT_EQ(p.y, points[i].y);
    EXPECT_EQ(p.z, points[i].z);
    EXPECT_EQ(p.r, points[i].r);
    EXPECT_EQ(p.g, points[i].g);
    EXPECT_EQ(p.b, points[i].b);
  }
}

}  // namespace
}  // namespace relmap::perception
