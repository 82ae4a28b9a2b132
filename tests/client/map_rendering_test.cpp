// The map colours (black→yellow relevance, blue→red choice) and their mapping onto
// the points through the server's point labels, over plain coloured points and over
// the points of a PCD file as the CLI reads it.
#include "map_rendering.h"

#include <gtest/gtest.h>

#include <limits>

#include "common/pcd/pcd_encoder.h"
#include "map_rendering_pcd.h"

namespace relmap::client {
namespace {

using image::Rgb;

TEST(RelevanceColour, RunsFromBlackThroughOliveToYellow) {
  EXPECT_EQ(RelevanceColour(0.0), (Rgb{0, 0, 0}));
  EXPECT_EQ(RelevanceColour(0.5), (Rgb{128, 128, 0}));  // 127.5 rounds up
  EXPECT_EQ(RelevanceColour(1.0), (Rgb{255, 255, 0}));
}

TEST(ChoiceColour, IsScaledToTheFramesMostLikelyTarget) {
  EXPECT_EQ(ChoiceColour(0.02, 0.02), (Rgb{255, 0, 0}));
  EXPECT_EQ(ChoiceColour(0.0, 0.02), (Rgb{0, 0, 255}));
  EXPECT_EQ(ChoiceColour(0.005, 0.02), (Rgb{64, 0, 191}));  // t = 1/4: 63.75, 191.25
  EXPECT_EQ(ChoiceColour(0.0, 0.0), (Rgb{0, 0, 255}));      // a map of zeros
}

// A 3×3 organized cloud: the left two columns are supervoxel 0, the right column
// supervoxel 1 except its bottom point, which no supervoxel holds; the centre is a hole.
// The cloud is read back from a PCD file, as the CLI reads the file it sent.
struct Scene {
  pcd::Points cloud;
  v1::ComputeMapsResponse maps;
};

Scene ThreeByThree() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<pcd::Point> points(9);
  for (int i = 0; i < 9; ++i) {
    points[i] = {0.1f * static_cast<float>(i % 3),
                 0.1f * static_cast<float>(i / 3),  // NOLINT(bugprone-integer-division): the row
                 1.0f,
                 255,
                 255,
                 255,
                 255};
  }
  points[4].x = points[4].y = points[4].z = nan;
  Scene scene{pcd::ReadPcd(pcd::EncodePcd(3, 3, points)).value(), {}};
  for (const int label : {0, 0, 1, 0, -1, 1, 0, 0, -1}) scene.maps.add_point_labels(label);
  v1::Supervoxel* zero = scene.maps.add_supervoxels();
  zero->set_id(0), zero->set_relevance(1.0), zero->set_choice(0.25);
  v1::Supervoxel* one = scene.maps.add_supervoxels();
  one->set_id(1), one->set_relevance(0.0), one->set_choice(0.75);
  scene.maps.set_target_supervoxel_id(1);
  return scene;
}

TEST(ColourPoints, PaintsEachPointWithItsSupervoxelAndOutlinesTheTarget) {
  const Scene scene = ThreeByThree();
  const StatusOr<std::vector<image::ColouredPoint>> points =
      ColourPoints(scene.cloud, scene.maps, MapKind::kRelevance);
  ASSERT_TRUE(points.ok()) << points.status().message();
  const Rgb yellow{255, 255, 0}, green{0, 255, 0}, white{255, 255, 255}, light{176, 176, 176};
  EXPECT_EQ((*points)[0].colour, yellow);
  EXPECT_EQ((*points)[2].colour, green);  // the target, on the picture's border
  EXPECT_EQ((*points)[4].colour, white);  // a hole
  EXPECT_EQ((*points)[8].colour, light);  // white point outside every supervoxel
}

TEST(ColourPoints, TheChoiceMapIsRedAtTheMostLikelyTarget) {
  Scene scene = ThreeByThree();
  scene.maps.set_target_supervoxel_id(0);
  const StatusOr<std::vector<image::ColouredPoint>> points =
      ColourPoints(scene.cloud, scene.maps, MapKind::kChoice);
  ASSERT_TRUE(points.ok());
  EXPECT_EQ((*points)[0].colour, (Rgb{0, 255, 0}));  // target outline
  EXPECT_EQ((*points)[5].colour, (Rgb{255, 0, 0}));  // choice 0.75 = the maximum
}

TEST(ColourPoints, LabelsOfAnotherCloudAreRejected) {
  Scene scene = ThreeByThree();
  scene.maps.add_point_labels(0);
  EXPECT_EQ(ColourPoints(scene.cloud, scene.maps, MapKind::kRelevance).status().code(),
            StatusCode::kInvalidArgument);
}

TEST(ColourPoints, ALabelTheMapsDoNotListIsRejected) {
  Scene scene = ThreeByThree();
  scene.maps.set_point_labels(0, 7);
  EXPECT_EQ(ColourPoints(scene.cloud, scene.maps, MapKind::kRelevance).status().code(),
            StatusCode::kInvalidArgument);
}

// The same 3×3 scene as plain points, each in its own colour: black on the left two
// columns, white on the right one (as in the cloud, so the only unlabelled point,
// bottom right, is white in both).
std::vector<image::ColouredPoint> ThreeByThreePoints() {
  const Scene scene = ThreeByThree();
  std::vector<image::ColouredPoint> points(9);
  for (std::size_t i = 0; i < 9; ++i) {
    const pcd::Point& p = scene.cloud.points[i];
    const std::uint8_t level = i % 3 == 2 ? 255 : 0;
    points[i] = {p.x, p.y, p.z, {level, level, level}};
  }
  return points;
}

TEST(ColourPointsOfPlainPoints, GreysTheUnlabelledPointsByTheirOwnColour) {
  const Scene scene = ThreeByThree();
  std::vector<image::ColouredPoint> points = ThreeByThreePoints();
  const StatusOr<std::vector<image::ColouredPoint>> coloured =
      ColourPoints(3, 3, points, scene.maps, MapKind::kRelevance);
  ASSERT_TRUE(coloured.ok()) << coloured.status().message();
  EXPECT_EQ((*coloured)[0].colour, (Rgb{255, 255, 0}));
  EXPECT_EQ((*coloured)[4].colour, (Rgb{255, 255, 255}));  // a hole
  EXPECT_EQ((*coloured)[8].colour, (Rgb{176, 176, 176}));  // white: 80 + 96
  points[8].colour = {0, 0, 0};
  EXPECT_EQ(ColourPoints(3, 3, points, scene.maps, MapKind::kRelevance)->at(8).colour,
            (Rgb{80, 80, 80}));  // black: 80 + 0
}

TEST(ColourPointsOfPlainPoints, AgreesWithThePointsOfThePcd) {
  const Scene scene = ThreeByThree();
  const auto plain = ColourPoints(3, 3, ThreeByThreePoints(), scene.maps, MapKind::kChoice);
  const auto decoded = ColourPoints(scene.cloud, scene.maps, MapKind::kChoice);
  ASSERT_TRUE(plain.ok() && decoded.ok());
  for (std::size_t i = 0; i < 9; ++i) EXPECT_EQ((*plain)[i].colour, (*decoded)[i].colour) << i;
}

TEST(ColourPointsOfPlainPoints, PointsThatDoNotFillTheSizeAreRejected) {
  const Scene scene = ThreeByThree();
  EXPECT_EQ(
      ColourPoints(3, 2, ThreeByThreePoints(), scene.maps, MapKind::kRelevance).status().code(),
      StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::client
