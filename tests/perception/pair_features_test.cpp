// The inlined pair features (one pair, and the vectorised batch) must bin every pair exactly
// as PCL's FPFHEstimation::computePointSPFHSignature does, in both directions.
#include "perception/pair_features.h"

#include <gtest/gtest.h>
#include <pcl/features/fpfh.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "perception/pair_batch.h"
#include "test_data.h"

namespace relmap::perception {
namespace {

// PCL's SPFH of point `p` over the neighbourhood {p, q}: the one pair's bins, each +100.
PairCode PclPairCode(const Eigen::Vector3f& p, const Eigen::Vector3f& np, const Eigen::Vector3f& q,
                     const Eigen::Vector3f& nq) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::PointCloud<pcl::Normal> normals;
  cloud.push_back({p.x(), p.y(), p.z()});
  cloud.push_back({q.x(), q.y(), q.z()});
  for (const Eigen::Vector3f* n : {&np, &nq}) {
    pcl::Normal normal;
    normal.getNormalVector3fMap() = *n;
    normals.push_back(normal);
  }
  pcl::FPFHEstimation<pcl::PointXYZ, pcl::Normal, pcl::FPFHSignature33> estimation;
  Eigen::MatrixXf f1 = Eigen::MatrixXf::Zero(1, kFpfhBins), f2 = f1, f3 = f1;
  estimation.computePointSPFHSignature(cloud, normals, 0, 0, {0, 1}, f1, f2, f3);
  Eigen::Index b1, b2, b3, row;
  f1.maxCoeff(&row, &b1), f2.maxCoeff(&row, &b2), f3.maxCoeff(&row, &b3);
  return static_cast<PairCode>(b1 * kFpfhBins * kFpfhBins + b2 * kFpfhBins + b3);
}

// Compares both directions of a pair; returns false (with a message) on the first mismatch.
::testing::AssertionResult SameAsPcl(const Eigen::Vector3f& p, const Eigen::Vector3f& np,
                                     const Eigen::Vector3f& q, const Eigen::Vector3f& nq) {
  Eigen::Vector4f p4, np4, q4, nq4;
  p4 << p, 0.0f, np4 << np, 0.0f, q4 << q, 0.0f, nq4 << nq, 0.0f;
  const PairCodes ours = ComputePairCodes(p4, np4, q4, nq4);
  const PairCode forward = PclPairCode(p, np, q, nq), backward = PclPairCode(q, nq, p, np);
  if (ours.forward == forward && ours.backward == backward) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "p " << p.transpose() << " n " << np.transpose() << " q " << q.transpose() << " n "
         << nq.transpose() << ": ours " << ours.forward << "/" << ours.backward << ", PCL "
         << forward << "/" << backward;
}

TEST(PairCodes, MatchPclOnEveryVoxelPairOfASceneWithinTheFpfhRadius) {
  std::vector<Eigen::Vector3f> positions, normals;
  testing::SmallSceneVoxels(positions, normals);
  ASSERT_FALSE(positions.empty());
  std::size_t pairs = 0;
  // Every 7th voxel against all voxels within 5 cm: ~10^5 pairs, planes, edges and spheres.
  for (std::size_t i = 0; i < positions.size(); i += 7) {
    for (std::size_t j = 0; j < positions.size(); ++j) {
      if (j == i || (positions[j] - positions[i]).squaredNorm() >= 0.05f * 0.05f) continue;
      ASSERT_TRUE(SameAsPcl(positions[i], normals[i], positions[j], normals[j]));
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 10000u);
}

TEST(PairCodes, MatchPclOnRandomPairs) {
  std::mt19937 rng(7);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  const auto random_unit = [&] {
    return Eigen::Vector3f(gauss(rng), gauss(rng), gauss(rng)).normalized();
  };
  for (int t = 0; t < 100000; ++t) {
    const Eigen::Vector3f p = 0.05f * random_unit(), q = 0.05f * random_unit();
    ASSERT_TRUE(SameAsPcl(p, random_unit(), q, random_unit()));
  }
}

// The cases where PCL's choice of source point is delicate: equal angles, normals along the
// line (no Darboux frame), coincident points and |cos| rounded above 1 (acosf gives NaN).
TEST(PairCodes, MatchPclOnDegenerateAndTiedPairs) {
  const Eigen::Vector3f p(0.1f, 0.2f, 1.0f), q(0.13f, 0.2f, 1.0f);
  const Eigen::Vector3f up(0, 0, 1), along(1, 0, 0), tilted = Eigen::Vector3f(1, 0, 1).normalized();
  EXPECT_TRUE(SameAsPcl(p, up, q, up));  // both perpendicular to the line: a tie
  EXPECT_TRUE(SameAsPcl(p, up, q, -up));
  EXPECT_TRUE(SameAsPcl(p, tilted, q, -tilted));  // |cos| equal, signs opposite: a tie
  EXPECT_TRUE(SameAsPcl(p, along, q, along));     // d × u = 0: f = 0 in PCL's FPFH
  EXPECT_TRUE(SameAsPcl(p, along, q, up));
  EXPECT_TRUE(SameAsPcl(p, up, p, tilted));              // coincident points
  EXPECT_TRUE(SameAsPcl(p, 1.0000002f * along, q, up));  // |cos| > 1: acosf is NaN
  EXPECT_TRUE(SameAsPcl(p, up, q, 1.0000002f * along));
  // Nearly tied angles, closer than the 1e-6 below which the acos are compared.
  for (int k = -40; k <= 40; ++k) {
    const Eigen::Vector3f n2 =
        Eigen::Vector3f(1, 0, 1 + static_cast<float>(k) * 1e-7f).normalized();
    EXPECT_TRUE(SameAsPcl(p, tilted, q, n2));
    EXPECT_TRUE(
        SameAsPcl(p, Eigen::Vector3f(1e-7f * static_cast<float>(k), 0, 1).normalized(), q, up));
  }
}

// The vectorised batch must give the one-pair kernel's codes, lane for lane, including the
// lanes it hands back to that kernel.
TEST(PairBatch, GivesTheCodesOfComputePairCodes) {
  std::vector<Eigen::Vector3f> positions, normals;
  testing::SmallSceneVoxels(positions, normals);
  ASSERT_FALSE(positions.empty());
  const Eigen::Vector3f up(0, 0, 1), along(1, 0, 0);
  positions.insert(positions.end(), {positions[0], positions[0], positions[0] + 0.01f * along});
  normals.insert(normals.end(), {up, along, along});  // coincident; normal along the line
  std::vector<Eigen::Vector4f, Eigen::aligned_allocator<Eigen::Vector4f>> p4, n4;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    p4.emplace_back(positions[i].x(), positions[i].y(), positions[i].z(), 0.0f);
    n4.emplace_back(normals[i].x(), normals[i].y(), normals[i].z(), 0.0f);
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < positions.size(); i += 5) {
    for (std::size_t j = 0; j < positions.size(); ++j) {
      if (j != i && (positions[j] - positions[i]).squaredNorm() < 0.05f * 0.05f) {
        pairs.emplace_back(i, j);
      }
    }
  }
  for (std::size_t k = positions.size() - 3; k < positions.size(); ++k) {
    pairs.emplace_back(0, k), pairs.emplace_back(k, 0);
  }
  PairBatch batch;
  std::size_t checked = 0;
  const auto check = [&](std::size_t k, PairCodes codes) {
    const auto [i, j] = pairs[k];
    const PairCodes expected = ComputePairCodes(p4[i], n4[i], p4[j], n4[j]);
    ASSERT_EQ(codes.forward, expected.forward) << i << " " << j;
    ASSERT_EQ(codes.backward, expected.backward) << i << " " << j;
    ++checked;
  };
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    batch.Add(p4[pairs[k].first], n4[pairs[k].first], p4[pairs[k].second], n4[pairs[k].second], k);
    if (batch.full()) batch.Flush(check);
  }
  batch.Flush(check);
  EXPECT_EQ(checked, pairs.size());
  EXPECT_GT(checked, 10000u);
}

// The f1 bin is decided by a polynomial atan when the angle is 5.7e-4 rad or more from a bin
// edge: that needs the polynomial within 1e-5 rad of atan.
TEST(AtanUnit, IsWithinOneHundredThousandthOfAtanOnTheUnitInterval) {
  double worst = 0.0;
  for (int k = 0; k <= 1000000; ++k) {
    const float t = static_cast<float>(k) / 1e6f;
    worst = std::max(worst, std::fabs(pair_features_internal::AtanUnit(t) - std::atan(double{t})));
  }
  EXPECT_LT(worst, 1e-5);
}

// Angles on and around every bin edge and the ±π seam, where the exact path must decide.
TEST(AngleBin, EqualsPclsBinOfAtan2fAroundEveryBinEdge) {
  for (int edge = 0; edge <= kFpfhBins; ++edge) {
    const double angle = -M_PI + 2.0 * M_PI * edge / kFpfhBins;
    for (int k = -2000; k <= 2000; ++k) {
      const double a = angle + k * 1e-6;
      for (const float r : {1.0f, 0.3f}) {
        const float y = r * static_cast<float>(std::sin(a)),
                    x = r * static_cast<float>(std::cos(a));
        ASSERT_EQ(pair_features_internal::AngleBin(y, x),
                  pair_features_internal::BinOf((std::atan2(y, x) + M_PI) *
                                                pair_features_internal::kInverseTwoPi))
            << "y " << y << " x " << x;
      }
    }
  }
  EXPECT_EQ(pair_features_internal::AngleBin(-0.0f, -1.0f), 0);             // atan2 = -π
  EXPECT_EQ(pair_features_internal::AngleBin(0.0f, -1.0f), kFpfhBins - 1);  // +π: clamped
}

}  // namespace
}  // namespace relmap::perception
