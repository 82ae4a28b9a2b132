// The tolerance threshold T(n, p, α) of §3.5 against the table of docs/method.md.
#include "cmm/tolerance_threshold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace relmap::cmm {
namespace {

struct Row {
  int n;
  double threshold;
};

class ToleranceThresholdTable48d : public ::testing::TestWithParam<Row> {};

TEST_P(ToleranceThresholdTable48d, MatchesTheSpecifiedValueAtAlphaOneQuarter) {
  // e.g. n = 49: (48·48/1)·(50/49)·F⁻¹₀.₇₅(48, 1) = 2304 · 1.020408 · 9.73675 = 22891.3
  const Row row = GetParam();
  EXPECT_NEAR(ToleranceThreshold(row.n, 48, 0.25), row.threshold, 1e-5 * row.threshold);
}

INSTANTIATE_TEST_SUITE_P(Alg, ToleranceThresholdTable48d,
                         ::testing::Values(Row{49, 22891.3}, Row{50, 4144.66}, Row{60, 346.292},
                                           Row{100, 111.691}, Row{1000, 57.1722}),
                         [](const ::testing::TestParamInfo<Row>& test_info) {
                           return std::string("n").append(std::to_string(test_info.param.n));
                         });

TEST(ToleranceThreshold, IsZeroWithoutMoreSamplesThanDimensions) {
  EXPECT_EQ(ToleranceThreshold(48, 48, 0.25), 0.0);
  EXPECT_EQ(ToleranceThreshold(3, 48, 0.25), 0.0);
}

TEST(ToleranceThreshold, AlphaOneGivesZeroAndAlphaZeroInfinity) {
  EXPECT_EQ(ToleranceThreshold(100, 48, 1.0), 0.0);
  EXPECT_TRUE(std::isinf(ToleranceThreshold(100, 48, 0.0)));
}

TEST(ToleranceThreshold, ShrinksAsAlphaGrows) {
  EXPECT_GT(ToleranceThreshold(100, 48, 0.1), ToleranceThreshold(100, 48, 0.25));
  EXPECT_GT(ToleranceThreshold(100, 48, 0.25), ToleranceThreshold(100, 48, 0.9));
}

TEST(InsideTolerance, ZeroThresholdContainsNothingNotEvenTheCentre) {
  EXPECT_FALSE(InsideTolerance(0.0, 0.0));
  EXPECT_TRUE(InsideTolerance(3.0, 3.0));
  EXPECT_FALSE(InsideTolerance(3.1, 3.0));
}

TEST(ToleranceThresholdTable, CachesTheSameValues) {
  ToleranceThresholdTable table(48, 0.25);
  EXPECT_EQ(table(60), ToleranceThreshold(60, 48, 0.25));
  EXPECT_EQ(table(49), ToleranceThreshold(49, 48, 0.25));
  EXPECT_EQ(table(60), ToleranceThreshold(60, 48, 0.25));
  EXPECT_EQ(table(10), 0.0);
}

}  // namespace
}  // namespace relmap::cmm
