// PointCloud2 as the bridge reads and writes it, checked byte by byte.
#include "cloud_conversion.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>

namespace relmap::ros_bridge {
namespace {

void PutBytes(const void* value, std::size_t size, std::vector<std::uint8_t>* data,
              std::size_t at) {
  std::memcpy(data->data() + at, value, size);  // the test host is little-endian, like ROS
}

// One point per call: x, y, z as float64 at 0, 8, 16, then 4 bytes of padding, then
// rgba as uint32 at 28: the layout of no camera, so that offsets are really read.
CloudMessage DoublesWithRgba(const std::vector<std::array<double, 3>>& xyz,
                             const std::vector<std::uint32_t>& argb) {
  CloudMessage cloud;
  cloud.width = static_cast<std::uint32_t>(xyz.size());
  cloud.fields = {{"x", 0, FieldType::kFloat64, 1},
                  {"y", 8, FieldType::kFloat64, 1},
                  {"z", 16, FieldType::kFloat64, 1},
                  {"rgba", 28, FieldType::kUint32, 1}};
  cloud.point_step = 32;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.data.resize(cloud.row_step);
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      PutBytes(&xyz[i][axis], 8, &cloud.data, i * 32 + std::size_t{8} * axis);
    }
    PutBytes(&argb[i], 4, &cloud.data, i * 32 + 28);
  }
  return cloud;
}

TEST(DecodeCloudMessage, ReadsFloat64CoordinatesAndUint32RgbaAtTheirOffsets) {
  const CloudMessage cloud =
      DoublesWithRgba({{0.5, -1.25, 2.0}, {NAN, 0, 1}}, {0xff102030U, 0x00a0b0c0U});
  StatusOr<pcd::Points> points = DecodeCloudMessage(cloud);
  ASSERT_TRUE(points.ok()) << points.status().message();
  ASSERT_EQ(points->points.size(), 2U);
  EXPECT_EQ(points->width, 2U);
  EXPECT_EQ(points->height, 1U);
  EXPECT_FLOAT_EQ(points->points[0].x, 0.5F);
  EXPECT_FLOAT_EQ(points->points[0].y, -1.25F);
  EXPECT_FLOAT_EQ(points->points[0].z, 2.0F);
  // 0xAARRGGBB: r = 0x10, g = 0x20, b = 0x30.
  EXPECT_EQ(points->points[0].r, 0x10);
  EXPECT_EQ(points->points[0].g, 0x20);
  EXPECT_EQ(points->points[0].b, 0x30);
  // A NaN in any coordinate makes a hole in all three.
  EXPECT_TRUE(std::isnan(points->points[1].y));
  EXPECT_TRUE(std::isnan(points->points[1].z));
  EXPECT_EQ(points->points[1].r, 0xa0);
}

TEST(DecodeCloudMessage, SkipsRowPaddingOfAnOrganizedCloud) {
  pcd::Points square{2, 2, {}};
  for (int i = 0; i < 4; ++i) {
    square.points.push_back({static_cast<float>(i), 0, 1, static_cast<std::uint8_t>(i), 0, 0});
  }
  CloudMessage cloud = EncodeCloudMessage(square, "camera", {1, 2});
  // Each row padded by 8 bytes, as some drivers align rows.
  std::vector<std::uint8_t> padded;
  for (std::uint32_t row = 0; row < 2; ++row) {
    const auto* begin = cloud.data.data() + std::size_t{row} * cloud.row_step;
    padded.insert(padded.end(), begin, begin + cloud.row_step);
    padded.insert(padded.end(), 8, 0xee);
  }
  cloud.row_step += 8;
  cloud.data = padded;
  StatusOr<pcd::Points> points = DecodeCloudMessage(cloud);
  ASSERT_TRUE(points.ok()) << points.status().message();
  EXPECT_EQ(points->height, 2U);
  for (int i = 0; i < 4; ++i) {
    EXPECT_FLOAT_EQ(points->points[i].x, static_cast<float>(i));
    EXPECT_EQ(points->points[i].r, i);
  }
}

TEST(DecodeCloudMessage, RefusesACloudWithoutColourNamingIt) {
  CloudMessage cloud = DoublesWithRgba({{0, 0, 1}}, {0});
  cloud.fields.pop_back();
  StatusOr<pcd::Points> points = DecodeCloudMessage(cloud);
  ASSERT_FALSE(points.ok());
  EXPECT_EQ(points.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(points.status().message().find("no rgb or rgba"), std::string::npos);
}

TEST(DecodeCloudMessage, RefusesBigEndianShortDataAndFieldsPastThePoint) {
  CloudMessage big = DoublesWithRgba({{0, 0, 1}}, {0});
  big.is_bigendian = true;
  EXPECT_FALSE(DecodeCloudMessage(big).ok());
  CloudMessage short_data = DoublesWithRgba({{0, 0, 1}}, {0});
  short_data.data.pop_back();
  EXPECT_FALSE(DecodeCloudMessage(short_data).ok());
  CloudMessage outside = DoublesWithRgba({{0, 0, 1}}, {0});
  outside.fields[3].offset = 30;  // 30 + 4 > point_step 32
  StatusOr<pcd::Points> points = DecodeCloudMessage(outside);
  ASSERT_FALSE(points.ok());
  EXPECT_NE(points.status().message().find("does not fit point_step"), std::string::npos);
}

TEST(TransformPoints, RotatesThenTranslatesAndLeavesHoles) {
  pcd::Points points{2, 1, {{1, 2, 3, 0, 0, 0}, {NAN, NAN, NAN, 0, 0, 0}}};
  // A quarter turn about z: (x, y, z) → (−y, x, z); then + (10, 0, −1).
  const double half = std::sqrt(0.5);
  TransformPoints({"table", {0, 0, half, half}, {10, 0, -1}}, &points);
  EXPECT_NEAR(points.points[0].x, 10 - 2, 1e-6);
  EXPECT_NEAR(points.points[0].y, 1, 1e-6);
  EXPECT_NEAR(points.points[0].z, 3 - 1, 1e-6);
  EXPECT_TRUE(std::isnan(points.points[1].x));
}

TEST(PackPoints, WritesThePackedLayoutOfTheApi) {
  const pcd::Points points{1, 1, {{1.5F, -2.0F, 0.25F, 7, 8, 9}}};
  const v1::Cloud cloud = PackPoints(points);
  ASSERT_TRUE(cloud.has_packed());
  const std::string& bytes = cloud.packed().points();
  ASSERT_EQ(bytes.size(), 16U);
  float xyz[3];
  std::memcpy(xyz, bytes.data(), 12);
  EXPECT_EQ(xyz[0], 1.5F);
  EXPECT_EQ(xyz[1], -2.0F);
  EXPECT_EQ(xyz[2], 0.25F);
  EXPECT_EQ(bytes[12], 7);
  EXPECT_EQ(bytes[13], 8);
  EXPECT_EQ(bytes[14], 9);
  EXPECT_EQ(static_cast<std::uint8_t>(bytes[15]), 0xff);
}

TEST(EncodeCloudMessage, DecodesBackToTheSamePoints) {
  const pcd::Points points{3, 1, {{1, 2, 3, 10, 20, 30}, {4, 5, 6, 40, 50, 60}, {NAN, NAN, NAN}}};
  const CloudMessage cloud = EncodeCloudMessage(points, "camera", {5, 6});
  EXPECT_EQ(cloud.frame_id, "camera");
  EXPECT_FALSE(cloud.is_dense);
  StatusOr<pcd::Points> back = DecodeCloudMessage(cloud);
  ASSERT_TRUE(back.ok()) << back.status().message();
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(back->points[i].x, points.points[i].x);
    EXPECT_EQ(back->points[i].z, points.points[i].z);
    EXPECT_EQ(back->points[i].g, points.points[i].g);
  }
  EXPECT_TRUE(std::isnan(back->points[2].x));
}

}  // namespace
}  // namespace relmap::ros_bridge
