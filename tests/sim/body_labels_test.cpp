// What each --labels scope posts of a target's body (body_labels.h), on hand-placed
// supervoxels.
#include "body_labels.h"

#include <gtest/gtest.h>

namespace relmap::sim {
namespace {

// Supervoxel i at (x[i], 0, 1), id i.
v1::ComputeMapsResponse MapsAt(const std::vector<double>& x) {
  v1::ComputeMapsResponse maps;
  for (std::size_t i = 0; i < x.size(); ++i) {
    v1::Supervoxel& s = *maps.add_supervoxels();
    s.set_id(static_cast<std::uint32_t>(i));
    s.mutable_centroid()->set_x(static_cast<float>(x[i]));
    s.mutable_centroid()->set_z(1);
  }
  return maps;
}

TEST(BodyLabels, TargetObjectAndMovedPostNoneAllAndAllWhenMoveable) {
  const v1::ComputeMapsResponse maps = MapsAt({0, 1, 2, 3});
  const std::vector<int> body = {3, 1, 2};
  for (const bool moveable : {true, false}) {
    EXPECT_TRUE(BodyLabels(LabelScope::kTarget, moveable, maps, 0, body).empty());
    EXPECT_EQ(BodyLabels(LabelScope::kObject, moveable, maps, 0, body),
              (std::vector<std::uint32_t>{3, 1, 2}));
  }
  EXPECT_EQ(BodyLabels(LabelScope::kMoved, true, maps, 0, body),
            (std::vector<std::uint32_t>{3, 1, 2}));
  EXPECT_TRUE(BodyLabels(LabelScope::kMoved, false, maps, 0, body).empty());
}

TEST(BodyLabels, NearPostsAMoveableBodyWholeAndTheNearestOfAStillOne) {
  // The target at x = 0.5; its body's twelve other supervoxels at 1..12 m, listed far first.
  std::vector<double> x = {0.5};
  std::vector<int> body;
  for (int i = 12; i >= 1; --i) {
    x.push_back(i);
    body.push_back(static_cast<int>(x.size()) - 1);
  }
  x.push_back(0.6);  // a supervoxel off the body, nearer than any of it
  const v1::ComputeMapsResponse maps = MapsAt(x);
  EXPECT_EQ(BodyLabels(LabelScope::kNear, true, maps, 0, body).size(), body.size());
  const std::vector<std::uint32_t> still = BodyLabels(LabelScope::kNear, false, maps, 0, body);
  ASSERT_EQ(still.size(), kNearSupervoxels);
  // Ids 12, 11, ... sit at 1, 2, ... m: the eight nearest, nearest first.
  for (std::size_t i = 0; i < still.size(); ++i) EXPECT_EQ(still[i], 12 - i) << i;
  // A still body no larger than the bound is posted whole, in its order.
  const std::vector<int> small = {body.begin(), body.begin() + 3};
  EXPECT_EQ(BodyLabels(LabelScope::kNear, false, maps, 0, small),
            (std::vector<std::uint32_t>{1, 2, 3}));
}

}  // namespace
}  // namespace relmap::sim
