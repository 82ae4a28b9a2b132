// A camera frame packed for the API reads back, through the server's own decoder,
// as the same points: 16 bytes each, little endian, holes as NaN.
#include "packed_cloud.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "perception/decode.h"

namespace relmap::sim {
namespace {

CameraFrame ThreePoints() {
  CameraFrame frame;
  frame.width = 3;
  frame.height = 1;
  frame.points = {{0.25f, -0.5f, 1.0f, 10, 20, 30},
                  {std::numeric_limits<float>::quiet_NaN(), 0, 0, 1, 2, 3},
                  {-1.5f, 2.0f, 3.75f, 255, 0, 128}};
  frame.body_ids = {1, kNoBody, 0};
  return frame;
}

TEST(PackCloud, LaysOutSixteenLittleEndianBytesPerPoint) {
  const v1::Cloud cloud = PackCloud(ThreePoints());
  ASSERT_TRUE(cloud.has_packed());
  EXPECT_EQ(cloud.packed().width(), 3u);
  EXPECT_EQ(cloud.packed().height(), 1u);
  const std::string& bytes = cloud.packed().points();
  ASSERT_EQ(bytes.size(), 48u);
  // z of the first point: 1.0f is 0x3f800000, low byte first.
  EXPECT_EQ(bytes.substr(8, 4), std::string("\x00\x00\x80\x3f", 4));
  // Its colour, then an opaque alpha.
  EXPECT_EQ(bytes.substr(12, 4), std::string("\x0a\x14\x1e\xff", 4));
}

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

TEST(PackCloud, AHoleIsAHoleInEveryCoordinate) {
  CameraFrame frame = ThreePoints();
  frame.points[0].y = std::numeric_limits<float>::infinity();
  const std::string bytes = PackCloud(frame).packed().points();
  float coordinates[3];
  std::memcpy(coordinates, bytes.data(), sizeof coordinates);
  EXPECT_TRUE(std::isnan(coordinates[0]) && std::isnan(coordinates[1]) &&
              std::isnan(coordinates[2]));
}

}  // namespace
}  // namespace relmap::sim
