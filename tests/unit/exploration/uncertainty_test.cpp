// Uncertainty (§4.1): the shape f against its check values, and the branch that
// favours the rarer class.
#include "exploration/uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relmap::exploration {
namespace {

TEST(UncertaintyShape, MatchesTheCheckValues) {
  // f(0.25) = −4·0.0625·(ln 0.25 − 1) = 0.25·2.386294 = 0.596574;
  // f(0.75) = −1.5·(ln 1.5 − 1) = 1.5·0.594535 = 0.891802;
  // f(1) = −2(ln 2 − 1) = 0.613706.
  EXPECT_DOUBLE_EQ(UncertaintyShape(0.0), 0.0);
  EXPECT_NEAR(UncertaintyShape(0.25), 0.596574, 1e-6);
  EXPECT_DOUBLE_EQ(UncertaintyShape(0.5), 1.0);
  EXPECT_NEAR(UncertaintyShape(0.75), 0.891802, 1e-6);
  EXPECT_NEAR(UncertaintyShape(1.0), 0.613706, 1e-6);
}

TEST(UncertaintyShape, PeaksAtOneHalf) {
  for (double x = 0.0; x <= 1.0; x += 0.01) EXPECT_LE(UncertaintyShape(x), 1.0 + 1e-15) << x;
}

TEST(Uncertainty, FavoursTheRarerClassAboveOneHalfWhenMoveablesAreTheMinority) {
  // |S1| <= |S0|: u = f(p), so p = 0.75 (likely moveable) beats p = 0.25.
  EXPECT_NEAR(Uncertainty(0.75, 3, 10), 0.891802, 1e-6);
  EXPECT_NEAR(Uncertainty(0.25, 3, 10), 0.596574, 1e-6);
  EXPECT_NEAR(Uncertainty(0.75, 5, 5), 0.891802, 1e-6);  // ties take this branch
}

TEST(Uncertainty, MirrorsWhenMoveablesAreTheMajority) {
  // |S1| > |S0|: u = f(1 − p), so p = 0.25 now beats p = 0.75.
  EXPECT_NEAR(Uncertainty(0.25, 10, 3), 0.891802, 1e-6);
  EXPECT_NEAR(Uncertainty(0.75, 10, 3), 0.596574, 1e-6);
}

TEST(Uncertainty, BugSwitchSendsTiesToTheOtherBranchWithPMinusOne) {
  // The later tag: ties use f(p − 1); f(−0.25) = f(0.25) on the x < 0.5 branch.
  EXPECT_NEAR(Uncertainty(0.75, 5, 5, /*uncertainty_bug=*/true), 0.596574, 1e-6);
  EXPECT_NEAR(Uncertainty(0.75, 3, 10, /*uncertainty_bug=*/true), 0.891802, 1e-6);
  // With moveables the majority, p = 0.25 gives f(−0.75) = 4·0.5625·(1 − ln 2.25).
  EXPECT_NEAR(Uncertainty(0.25, 10, 3, /*uncertainty_bug=*/true), 2.25 * (1 - std::log(2.25)),
              1e-12);
}

}  // namespace
}  // namespace relmap::exploration
