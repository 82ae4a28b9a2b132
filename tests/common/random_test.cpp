// The session RNG: reproducible from its seed and from a saved state, unbiased.
#include "common/random.h"

#include <gtest/gtest.h>

#include <vector>

namespace relmap {
namespace {

TEST(Random, SameSeedGivesTheSameStream) {
  Random a(42);
  Random b(42);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.NextBits(), b.NextBits());
}

TEST(Random, DifferentSeedsGiveDifferentStreams) {
  Random a(1);
  Random b(2);
  EXPECT_NE(a.NextBits(), b.NextBits());
}

TEST(Random, RestoredStateContinuesTheStream) {
  Random a(7);
  for (int i = 0; i < 10; ++i) a.NextBits();
  Random b = Random::FromState(a.state());
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.UniformIndex(1000), b.UniformIndex(1000));
}

TEST(Random, UniformUnitLiesInTheHalfOpenUnitInterval) {
  Random random(3);
  for (int i = 0; i < 10000; ++i) {
    const double u = random.UniformUnit();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
}

TEST(Random, UniformIndexCoversItsRangeEvenly) {
  // 60000 draws over 6 values: each count has mean 10000 and standard
  // deviation ≈ 91; 5 standard deviations leave a false alarm at ~1e-6.
  Random random(5);
  std::vector<int> counts(6, 0);
  for (int i = 0; i < 60000; ++i) {
    const std::size_t k = random.UniformIndex(6);
    ASSERT_LT(k, 6u);
    ++counts[k];
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 460);
}

TEST(Random, UniformIndexOfOneIsZero) {
  Random random(9);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(random.UniformIndex(1), 0u);
}

}  // namespace
}  // namespace relmap
