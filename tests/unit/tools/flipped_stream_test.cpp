// relmap-bench-learning's --flip: exactly the rounded fraction of the training labels
// flipped, the same ones for the same seed, the test set untouched.
#include <gtest/gtest.h>

#include "learning_bench/streams.h"

namespace relmap::learning_bench {
namespace {

Stream Alternating(int train, int test) {
  Stream stream{"real", {}, {}};
  for (auto [set, n] : {std::pair{&stream.train, train}, std::pair{&stream.test, test}}) {
    set->features = Eigen::MatrixXd::Zero(n, 2);
    for (int i = 0; i < n; ++i) set->labels.push_back(i % 2);
  }
  return stream;
}

int Differences(const std::vector<int>& a, const std::vector<int>& b) {
  int n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i] ? 1 : 0;
  return n;
}

TEST(FlippedStream, FlipsExactlyTheRoundedFractionOfTheTrainingLabelsOnly) {
  const Stream clean = Alternating(403, 50);
  const Stream flipped = FlippedStream(clean, 0.2, 1);
  EXPECT_EQ(flipped.name, "real-flip20");
  EXPECT_EQ(Differences(clean.train.labels, flipped.train.labels), 81);  // round(0.2 × 403)
  EXPECT_EQ(flipped.test.labels, clean.test.labels);
  EXPECT_EQ(flipped.train.features, clean.train.features);
}

TEST(FlippedStream, TheSameSeedFlipsTheSameLabelsAnotherSeedOthers) {
  const Stream clean = Alternating(400, 10);
  EXPECT_EQ(FlippedStream(clean, 0.2, 1).train.labels, FlippedStream(clean, 0.2, 1).train.labels);
  EXPECT_NE(FlippedStream(clean, 0.2, 1).train.labels, FlippedStream(clean, 0.2, 2).train.labels);
}

}  // namespace
}  // namespace relmap::learning_bench
