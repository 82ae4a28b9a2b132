// A supervoxel is an object when at least half of its points hit a moveable body
// (ALGORITHMS §6), its points named by the server's point labels.
#include "ground_truth.h"

#include <gtest/gtest.h>

namespace relmap::sim {
namespace {

// Bodies 1 and 2 are moveable, 0 (the table) and 3 are not.
bool Moveable(std::int32_t body) { return body == 1 || body == 2; }

// A 4×2 frame: the body behind every point and the supervoxel the server put it in.
struct Frame {
  CameraFrame frame;
  v1::ComputeMapsResponse maps;
};

Frame MakeFrame(const std::vector<std::int32_t>& bodies, const std::vector<int>& labels,
                int supervoxels) {
  Frame f;
  f.frame.width = 4;
  f.frame.height = 2;
  f.frame.points.resize(8);
  f.frame.body_ids = bodies;
  for (const int label : labels) f.maps.add_point_labels(label);
  for (int id = 0; id < supervoxels; ++id)
    f.maps.add_supervoxels()->set_id(static_cast<unsigned>(id));
  return f;
}

TEST(SupervoxelGroundTruth, HalfOfThePointsOnMoveableBodiesMakeAnObject) {
  // Supervoxel 0: bodies 1, 1, 0 → 2/3 moveable → object.
  // Supervoxel 1: bodies 2, 3 → 1/2 moveable → object (the bound is inclusive).
  // Supervoxel 2: bodies 0, 3 and an unsegmented point of body 1 → 0/2 → background.
  const Frame f = MakeFrame({1, 1, 0, 2, 3, 0, 3, 1}, {0, 0, 0, 1, 1, 2, 2, -1}, 3);
  const StatusOr<std::vector<bool>> object = SupervoxelGroundTruth(f.frame, f.maps, Moveable);
  ASSERT_TRUE(object.ok()) << object.status().message();
  EXPECT_EQ(*object, (std::vector<bool>{true, true, false}));
}

TEST(SupervoxelGroundTruth, HolesCountForNoBody) {
  // Supervoxel 0: a hole (no body) and body 2 → 1/2 → object; supervoxel 1: a hole
  // and three table points → 0/4 → background.
  const Frame f = MakeFrame({kNoBody, 2, kNoBody, 0, 0, 0, 3, 3}, {0, 0, 1, 1, 1, 1, -1, -1}, 2);
  EXPECT_EQ(*SupervoxelGroundTruth(f.frame, f.maps, Moveable), (std::vector<bool>{true, false}));
}

TEST(SupervoxelGroundTruth, FollowsTheOrderOfTheMapsNotTheIds) {
  // The maps list supervoxel 1 before supervoxel 0.
  Frame f = MakeFrame({1, 1, 1, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 1, 1, 1, 1}, 0);
  f.maps.add_supervoxels()->set_id(1);
  f.maps.add_supervoxels()->set_id(0);
  EXPECT_EQ(*SupervoxelGroundTruth(f.frame, f.maps, Moveable), (std::vector<bool>{false, true}));
}

TEST(SupervoxelGroundTruth, MapsWithoutPointLabelsAreRejected) {
  Frame f = MakeFrame({1, 1, 1, 1, 0, 0, 0, 0}, {}, 2);
  EXPECT_EQ(SupervoxelGroundTruth(f.frame, f.maps, Moveable).status().code(),
            StatusCode::kInvalidArgument);
}

TEST(SupervoxelGroundTruth, ALabelTheMapsDoNotListIsRejected) {
  Frame f = MakeFrame({1, 1, 1, 1, 0, 0, 0, 0}, {0, 0, 0, 0, 5, 1, 1, 1}, 2);
  EXPECT_EQ(SupervoxelGroundTruth(f.frame, f.maps, Moveable).status().code(),
            StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace relmap::sim
