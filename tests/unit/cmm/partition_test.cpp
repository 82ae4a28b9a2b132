// The partition of SPLIT (§3.6): 1-NN graph components, merged down to two.
#include "cmm/partition.h"

#include <gtest/gtest.h>

#include <limits>

#include "common/random.h"

namespace relmap::cmm {
namespace {

Eigen::MatrixXd Columns(std::initializer_list<std::pair<double, double>> points) {
  Eigen::MatrixXd m(2, static_cast<Eigen::Index>(points.size()));
  int j = 0;
  for (const auto& [x, y] : points) m.col(j++) << x, y;
  return m;
}

TEST(PartitionInTwo, SeparatesTwoClusters) {
  const auto points = Columns({{0, 0}, {5, 5}, {0.1, 0}, {5.1, 5}, {0, 0.1}});
  EXPECT_EQ(PartitionInTwo(points), (std::vector<int>{0, 1, 0, 1, 0}));
}

TEST(PartitionInTwo, LeavesAConnectedNearestNeighbourGraphWhole) {
  // Evenly spaced points: each links to a neighbour, the graph is one chain.
  const auto points = Columns({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}});
  EXPECT_TRUE(PartitionInTwo(points).empty());
}

TEST(PartitionInTwo, MergesTheTwoClosestOfThreeSets) {
  // Pairs at x = 0, 1 and 10: three 1-NN components; the centroids at 0 and 1
  // are closest, so those two pairs form one group.
  const auto points = Columns({{0, 0}, {0.01, 0}, {1, 0}, {1.01, 0}, {10, 0}, {10.01, 0}});
  EXPECT_EQ(PartitionInTwo(points), (std::vector<int>{0, 0, 0, 0, 1, 1}));
}

TEST(PartitionInTwo, PutsTheFirstSampleInGroupZero) {
  const auto points = Columns({{10, 0}, {10.01, 0}, {0, 0}, {0.01, 0}, {1, 0}, {1.01, 0}});
  EXPECT_EQ(PartitionInTwo(points), (std::vector<int>{0, 0, 1, 1, 1, 1}));
}

TEST(PartitionInTwo, DuplicatePointsDoNotSplit) {
  const auto points = Columns({{1, 1}, {1, 1}, {1, 1}});
  EXPECT_TRUE(PartitionInTwo(points).empty());
}

TEST(PartitionInTwo, ReadsADatasetsSamplesInPlaceAsTheirGatheredCopy) {
  // Three sets; the component holds samples 1..6 of the dataset, in a shuffled order.
  const Eigen::MatrixXd all = Columns({{9, 9}, {0, 0}, {10, 0}, {0, 1}, {10, 1}, {4, 0}, {4, 1}});
  Dataset data(2);
  for (Eigen::Index j = 0; j < all.cols(); ++j) data.Append(all.col(j), 0);
  const std::vector<int> indices{3, 1, 2, 6, 4, 5};
  Eigen::MatrixXd gathered(2, 6);
  for (int j = 0; j < 6; ++j) gathered.col(j) = all.col(indices[j]);
  const std::vector<int> nearest = NearestNeighbours(gathered).nearest;
  const std::vector<int> expected = PartitionInTwo(gathered, nearest);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(PartitionInTwo(data, indices, nearest), expected);
}

TEST(NearestNeighbours, IsTheGraphOfEveryPairsSquaredDistance) {
  // 48-d points with duplicates (ties go to the lower index), against the
  // pairwise SquaredDistance that the incremental update uses: the same bits.
  Random random(7);
  Eigen::MatrixXd points(48, 61);
  for (Eigen::Index j = 0; j < points.cols(); ++j) {
    for (Eigen::Index k = 0; k < points.rows(); ++k) points(k, j) = random.UniformUnit();
  }
  points.col(40) = points.col(3);
  points.col(50) = points.col(3);
  const NearestNeighbourGraph graph = NearestNeighbours(points);
  const int n = static_cast<int>(points.cols());
  for (int i = 0; i < n; ++i) {
    int nearest = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const double d = SquaredDistance(points.col(i).data(), 1, points.col(j).data(), 1, 48);
      if (d < best) best = d, nearest = j;
    }
    EXPECT_EQ(graph.nearest[i], nearest) << i;
    EXPECT_EQ(graph.squared_distance[i], best) << i;
  }
  EXPECT_EQ(graph.nearest[40], 3);
  EXPECT_EQ(graph.nearest[3], 40);
}

TEST(PartitionInTwo, NeedsTwoPoints) { EXPECT_TRUE(PartitionInTwo(Columns({{1, 1}})).empty()); }

}  // namespace
}  // namespace relmap::cmm
