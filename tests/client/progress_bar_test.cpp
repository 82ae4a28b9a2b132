// The progress line's arithmetic: fraction, rate and remaining time.
#include "progress_bar.h"

#include <gtest/gtest.h>

namespace relmap::client {
namespace {

TEST(ProgressBarLine, ShowsFractionRateAndRemainingTime) {
  // 500 of 1000 in 2 s: 250/s, 500 left → 2 s.
  EXPECT_EQ(ProgressBar::Line(500, 1000, "samples", 2.0, 10),
            "[#####.....]  50% 500/1000 samples  250/s  eta 2 s");
}

TEST(ProgressBarLine, AFinishedRunHasNoRemainingTime) {
  EXPECT_EQ(ProgressBar::Line(40, 40, "samples", 4.0, 4), "[####] 100% 40/40 samples  10/s");
}

TEST(ProgressBarLine, NothingToDoIsComplete) {
  EXPECT_EQ(ProgressBar::Line(0, 0, "samples", 0.0, 4), "[####] 100% 0/0 samples  0/s");
}

}  // namespace
}  // namespace relmap::client
