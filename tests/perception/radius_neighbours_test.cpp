// The grid radius search must return KdTreeFLANN's neighbour sets and squared distances,
// in the documented row and neighbour order.
#include "perception/radius_neighbours.h"

#include <gtest/gtest.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "test_data.h"

namespace relmap::perception {
namespace {

void ExpectSameAsKdTree(const std::vector<Eigen::Vector3f>& positions, float radius) {
  const RadiusNeighbours table = FindRadiusNeighbours(positions, radius, 2);
  ASSERT_EQ(table.order.size(), positions.size());
  ASSERT_EQ(table.begin.size(), positions.size() + 1);
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (const Eigen::Vector3f& p : positions) cloud->push_back({p.x(), p.y(), p.z()});
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  pcl::Indices found;
  std::vector<float> found_d2;
  for (std::size_t r = 0; r < positions.size(); ++r) {
    const std::uint32_t input = table.order[r];
    tree.radiusSearch((*cloud)[input], radius, found, found_d2);
    std::vector<std::pair<std::uint32_t, float>> theirs, ours;
    for (std::size_t k = 0; k < found.size(); ++k) {
      theirs.emplace_back(static_cast<std::uint32_t>(found[k]), found_d2[k]);
    }
    for (std::size_t e = table.begin[r]; e < table.begin[r + 1]; ++e) {
      if (e > table.begin[r]) {
        ASSERT_LT(table.neighbour[e - 1], table.neighbour[e]);
      }
      const Eigen::Vector3f &q = positions[input], &p = positions[table.order[table.neighbour[e]]];
      ours.emplace_back(table.order[table.neighbour[e]],
                        FlannSquaredDistance(q.x(), q.y(), q.z(), p.x(), p.y(), p.z()));
    }
    std::sort(theirs.begin(), theirs.end());
    std::sort(ours.begin(), ours.end());
    ASSERT_EQ(ours, theirs) << "point " << input;  // same sets, bitwise equal distances
  }
}

TEST(FindRadiusNeighbours, EqualsKdTreeFlannOnTheVoxelsOfAScene) {
  std::vector<Eigen::Vector3f> positions, normals;
  testing::SmallSceneVoxels(positions, normals);
  ASSERT_FALSE(positions.empty());
  ExpectSameAsKdTree(positions, 0.05f);
}

// Points on a lattice whose spacing is the radius: many distances equal the radius up to
// rounding, where "closer than" is decided by the last bit.
TEST(FindRadiusNeighbours, EqualsKdTreeFlannOnALatticeAtTheRadius) {
  std::vector<Eigen::Vector3f> positions;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-1e-7f, 1e-7f);
  for (int x = -4; x <= 4; ++x) {
    for (int y = -4; y <= 4; ++y) {
      for (int z = 0; z <= 2; ++z) {
        positions.emplace_back(0.05f * static_cast<float>(x) + jitter(rng),
                               0.05f * static_cast<float>(y), 1.0f + 0.05f * static_cast<float>(z));
      }
    }
  }
  ExpectSameAsKdTree(positions, 0.05f);
}

TEST(FindRadiusNeighbours, HandlesNoPointAndOnePoint) {
  EXPECT_EQ(FindRadiusNeighbours({}, 0.05f, 2).begin.back(), 0u);
  const RadiusNeighbours one = FindRadiusNeighbours({Eigen::Vector3f(1, 2, 3)}, 0.05f, 2);
  ASSERT_EQ(one.begin.back(), 1u);
  EXPECT_EQ(one.neighbour[0], 0u);
}

}  // namespace
}  // namespace relmap::perception
