// What a physical-mode session learned, paired with its pushes, and the three files.
#include "learned_samples.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

namespace relmap::sim {
namespace {

IterationRecord Pushed(int iteration, std::uint32_t target, bool label, bool truth) {
  IterationRecord record;
  record.iteration = iteration;
  record.target = target;
  record.label = label;
  record.truth = truth;
  return record;
}

void AddSample(v1::SessionState& state, bool label, std::vector<double> values) {
  v1::LabelledFeature& sample = *state.add_samples();
  sample.set_label(label ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
  for (const double v : values) sample.mutable_feature()->add_values(v);
}

std::string Read(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(LearnedSamples, PairsEachLearnedPushWithTheNextSampleSkippingPushesThatTaughtNothing) {
  IterationRecord blocked;  // a push the simulator could not execute: no label
  blocked.iteration = 2;
  blocked.target = 9;
  const std::vector<IterationRecord> iterations = {Pushed(1, 4, true, true), blocked,
                                                   Pushed(3, 7, false, true)};
  v1::SessionState state;
  AddSample(state, true, {0.25, 0.5});
  AddSample(state, false, {0.75, 1.0});
  StatusOr<std::vector<LearnedSample>> samples = PairLearnedSamples(iterations, state);
  ASSERT_TRUE(samples.ok()) << samples.status().message();
  ASSERT_EQ(samples->size(), 2u);
  EXPECT_EQ((*samples)[0].iteration, 1);
  EXPECT_EQ((*samples)[0].target, 4u);
  EXPECT_EQ((*samples)[0].features, (std::vector<double>{0.25, 0.5}));
  EXPECT_EQ((*samples)[1].iteration, 3);
  EXPECT_FALSE((*samples)[1].label);  // the detector's "not moved" ...
  EXPECT_TRUE((*samples)[1].truth);   // ... of a moveable target
}

TEST(LearnedSamples, ASessionThatLearnedMoreOrOtherLabelsDoesNotPair) {
  const std::vector<IterationRecord> iterations = {Pushed(1, 4, true, true)};
  v1::SessionState more;  // the target and a supervoxel seen moving with it
  AddSample(more, true, {0.0});
  AddSample(more, true, {1.0});
  EXPECT_EQ(PairLearnedSamples(iterations, more).status().code(), StatusCode::kFailedPrecondition);
  v1::SessionState fewer;
  EXPECT_EQ(PairLearnedSamples(iterations, fewer).status().code(), StatusCode::kFailedPrecondition);
  v1::SessionState other;
  AddSample(other, false, {0.0});
  EXPECT_EQ(PairLearnedSamples(iterations, other).status().code(), StatusCode::kFailedPrecondition);
}

TEST(LearnedSamples, WritesTheLearnedLabelsTheTruthAndWhereEachRowCameFrom) {
  const std::string dir = ::testing::TempDir() + "/learned_" + std::to_string(::getpid());
  const std::vector<LearnedSample> samples = {{1, 4, true, true, {0.25, 0.5}},
                                              {3, 7, false, true, {0.1, 1.0}}};
  const std::string csv = dir + ".csv", truth = dir + ".truth.csv", rows = dir + ".csv.frames";
  ASSERT_TRUE(WriteLearnedSamples(samples, csv, truth, rows).ok());
  EXPECT_EQ(Read(csv), "label,f1,f2\n1,0.25,0.5\n0,0.1,1\n");
  EXPECT_EQ(Read(truth), "label,f1,f2\n1,0.25,0.5\n1,0.1,1\n");
  EXPECT_EQ(Read(rows), "iteration,target,label,truth\n1,4,1,1\n3,7,0,1\n");
  for (const std::string& path : {csv, truth, rows}) std::remove(path.c_str());
}

TEST(LearnedSamples, AnUnwritableFileIsAnInternalErrorNamingIt) {
  const Status status = WriteLearnedSamples({}, "/nonexistent/dir/a.csv", "", "/nonexistent/dir/b");
  EXPECT_EQ(status.code(), StatusCode::kInternal);
  EXPECT_NE(status.message().find("/nonexistent/dir/a.csv"), std::string::npos);
}

}  // namespace
}  // namespace relmap::sim
