// The maps' clouds and the target pose, on a 2×2 frame labelled by hand.
#include "map_clouds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace relmap::ros_bridge {
namespace {

// Points 0 and 3 in supervoxel 0, point 1 unsegmented, point 2 in supervoxel 1, the target.
v1::ComputeMapsResponse HandMaps() {
  v1::ComputeMapsResponse maps;
  maps.set_frame_id(7);
  for (int label : {0, -1, 1, 0}) maps.add_point_labels(label);
  v1::Supervoxel* first = maps.add_supervoxels();
  first->set_id(0);
  first->set_relevance(0.25);
  first->set_choice(0.75);
  v1::Supervoxel* second = maps.add_supervoxels();
  second->set_id(1);
  second->set_relevance(1.0);
  second->set_choice(0.25);
  second->mutable_centroid()->set_x(0.1F);
  second->mutable_centroid()->set_y(0.2F);
  second->mutable_centroid()->set_z(0.9F);
  second->mutable_normal()->set_y(-1.0F);
  maps.set_target_supervoxel_id(1);
  return maps;
}

pcd::Points HandPoints() {
  pcd::Points points{2, 2, {}};
  for (int i = 0; i < 4; ++i) points.points.push_back({static_cast<float>(i), 0, 1, 50, 50, 50});
  return points;
}

float FloatAt(const CloudMessage& cloud, std::size_t point, std::uint32_t offset) {
  float value = 0;
  std::memcpy(&value, cloud.data.data() + point * cloud.point_step + offset, 4);
  return value;
}

std::uint32_t Uint32At(const CloudMessage& cloud, std::size_t point, std::uint32_t offset) {
  std::uint32_t value = 0;
  std::memcpy(&value, cloud.data.data() + point * cloud.point_step + offset, 4);
  return value;
}

TEST(MapCloud, KeepsTheSegmentedPointsWithTheirRelevanceAndSupervoxel) {
  StatusOr<CloudMessage> cloud =
      MapCloud(HandPoints(), HandMaps(), client::MapKind::kRelevance, "table", {3, 4});
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  EXPECT_EQ(cloud->frame_id, "table");
  EXPECT_EQ(cloud->stamp, (Stamp{3, 4}));
  ASSERT_EQ(cloud->width, 3U);  // points 0, 2, 3
  EXPECT_EQ(cloud->height, 1U);
  std::vector<std::string> names;
  for (const PointField& field : cloud->fields) names.push_back(field.name);
  EXPECT_EQ(names, (std::vector<std::string>{"x", "y", "z", "rgb", "intensity", "supervoxel"}));
  EXPECT_EQ(FloatAt(*cloud, 0, 0), 0.0F);
  EXPECT_EQ(FloatAt(*cloud, 1, 0), 2.0F);
  EXPECT_EQ(FloatAt(*cloud, 2, 0), 3.0F);
  EXPECT_EQ(FloatAt(*cloud, 0, 16), 0.25F);
  EXPECT_EQ(FloatAt(*cloud, 1, 16), 1.0F);
  EXPECT_EQ(Uint32At(*cloud, 1, 20), 1U);
  EXPECT_EQ(Uint32At(*cloud, 2, 20), 0U);
  // Relevance 0.25 → (round(255·0.25), same, 0) = (64, 64, 0); the target, every point
  // of which borders the 2×2 picture, is outlined green.
  EXPECT_EQ(Uint32At(*cloud, 0, 12), (64U << 16) | (64U << 8));
  EXPECT_EQ(Uint32At(*cloud, 1, 12), 255U << 8);
}

TEST(MapCloud, CarriesTheChoiceProbabilityAsIntensity) {
  StatusOr<CloudMessage> cloud =
      MapCloud(HandPoints(), HandMaps(), client::MapKind::kChoice, "table", {3, 4});
  ASSERT_TRUE(cloud.ok()) << cloud.status().message();
  EXPECT_EQ(FloatAt(*cloud, 0, 16), 0.75F);
  EXPECT_EQ(FloatAt(*cloud, 1, 16), 0.25F);
  // Choice 0.75 of at most 0.75 → t = 1: (255, 0, 0).
  EXPECT_EQ(Uint32At(*cloud, 2, 12), 255U << 16);
}

TEST(MapCloud, RefusesMapsOfAnotherCloud) {
  pcd::Points three{3, 1, {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}}};
  EXPECT_FALSE(MapCloud(three, HandMaps(), client::MapKind::kRelevance, "t", {}).ok());
}

TEST(TargetOf, PlacesThePoseAtTheCentroidFacingTheNormal) {
  const std::optional<TargetPose> pose = TargetOf(HandMaps(), "table", {3, 4});
  ASSERT_TRUE(pose.has_value());
  EXPECT_EQ(pose->supervoxel_id, 1U);
  EXPECT_FLOAT_EQ(static_cast<float>(pose->position.z), 0.9F);
  // x onto −y: a quarter turn about −z, q = (0, 0, −sin 45°, cos 45°).
  EXPECT_NEAR(pose->orientation.z, -std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(pose->orientation.w, std::sqrt(0.5), 1e-12);
  v1::ComputeMapsResponse none = HandMaps();
  none.clear_target_supervoxel_id();
  EXPECT_FALSE(TargetOf(none, "table", {}).has_value());
}

TEST(RotationFromXAxis, HandlesTheOppositeAndTheZeroVector) {
  const Quaternion opposite = RotationFromXAxis({-2, 0, 0});
  EXPECT_EQ(opposite.z, 1.0);
  EXPECT_EQ(opposite.w, 0.0);
  const Quaternion zero = RotationFromXAxis({0, 0, 0});
  EXPECT_EQ(zero.w, 1.0);
  const Quaternion same = RotationFromXAxis({3, 0, 0});
  EXPECT_NEAR(same.w, 1.0, 1e-12);
}

}  // namespace
}  // namespace relmap::ros_bridge
