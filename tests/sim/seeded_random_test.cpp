// The simulator's random draws: in range, reproducible, and independent of the
// standard library's distributions.
#include "seeded_random.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/random.h"

namespace relmap::sim {
namespace {

TEST(SeededRandom, TheSameSeedAndStreamGiveTheSameDraws) {
  SeededRandom a(42, 1), b(42, 1), c(42, 2);
  bool streams_differ = false;
  for (int i = 0; i < 100; ++i) {
    const double x = a.Uniform01();
    EXPECT_EQ(x, b.Uniform01());
    streams_differ = streams_differ || x != c.Uniform01();
  }
  EXPECT_TRUE(streams_differ);
}

TEST(SeededRandom, UniformDrawsStayInTheirInterval) {
  SeededRandom random(3);
  for (int i = 0; i < 10000; ++i) {
    const double u = random.Uniform01();
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
    const double x = random.Uniform(-2.0, 0.5);
    EXPECT_GE(x, -2.0);
    EXPECT_LT(x, 0.5);
    EXPECT_LT(random.Below(7), 7u);
  }
  EXPECT_EQ(random.Uniform(0.25, 0.25), 0.25);  // a flat spawn region
}

TEST(SeededRandom, GaussianDrawsHaveUnitVariance) {
  SeededRandom random(5);
  double sum = 0, sum_sq = 0;
  constexpr int kN = 200000;
  for (int i = 0; i < kN; ++i) {
    const double g = random.Gaussian();
    sum += g;
    sum_sq += g * g;
  }
  EXPECT_NEAR(sum / kN, 0.0, 0.01);
  EXPECT_NEAR(sum_sq / kN, 1.0, 0.01);
}

TEST(SeededRandom, RotationsAreUnitAndCoverTheSphere) {
  SeededRandom random(9);
  Eigen::Vector3d mean_axis = Eigen::Vector3d::Zero();
  constexpr int kN = 20000;
  for (int i = 0; i < kN; ++i) {
    const Eigen::Quaterniond q = random.Rotation();
    EXPECT_NEAR(q.norm(), 1.0, 1e-12);
    mean_axis += q * Eigen::Vector3d::UnitZ();
  }
  // A uniform rotation sends z to a uniform direction: the mean direction is ~0
  // (standard error 1/sqrt(3N) per axis = 0.004).
  EXPECT_LT((mean_axis / kN).norm(), 0.02);
}

TEST(SeededRandom, DrawsAreExplicitArithmeticOnMt19937_64) {
  // std::mt19937_64's 10000th output for the default seed is fixed by the C++
  // standard; Uniform01 is its top 53 bits / 2^53, whatever the library.
  std::mt19937_64 engine(SplitMix64At(0 ^ SplitMix64At(0)));
  SeededRandom random(0, 0);
  const std::uint64_t word = engine();
  EXPECT_EQ(random.Uniform01(), static_cast<double>(word >> 11) / 9007199254740992.0);
}

}  // namespace
}  // namespace relmap::sim
