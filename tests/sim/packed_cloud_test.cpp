// A camera frame packed for the API: 16 bytes per point, little endian, holes as NaN.
// tests/integration/sim_packing_contract_test.cpp reads it back with the server's
// decoder.
#include "packed_cloud.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "sim/three_point_frame.h"

namespace relmap::sim {
namespace {

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
