// What the run's files say: the CSV rows of hand-made iterations, the summary's
// aggregates, and the curves' mean with its min–max envelope.
#include "curves.h"

#include <gtest/gtest.h>

#include <sstream>

#include "spread.h"

namespace relmap::sim {
namespace {

IterationRecord Iteration(int iteration, std::optional<double> accuracy) {
  IterationRecord record;
  record.iteration = iteration;
  record.supervoxels = 300;
  record.thresholded = {0.5, 1.0, accuracy};
  record.soft = {std::nullopt, 0.25, 0.5};
  record.model = {3, 4, 1, 2};
  record.timings.iteration_ms = 100;
  record.timings.maps_ms = 60;
  return record;
}

ReplicationResult Replication(int r, std::vector<std::optional<double>> accuracies) {
  ReplicationResult result;
  result.replication = r;
  result.seed = 10 + static_cast<std::uint64_t>(r);
  result.session_id = std::to_string(r);
  result.session_id.insert(result.session_id.begin(), 's');  // not "s" + …: GCC 12's -Wrestrict
  for (std::size_t i = 0; i < accuracies.size(); ++i) {
    result.iterations.push_back(Iteration(static_cast<int>(i) + 1, accuracies[i]));
  }
  return result;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(IterationCsv, OneRowPerIterationWithEmptyFieldsForWhatIsUndefinedOrAbsent) {
  ReplicationResult r = Replication(0, {0.75, std::nullopt});
  r.iterations[0].target = 17;
  r.iterations[0].label = true;
  r.iterations[0].truth = false;
  r.iterations[0].mislabelled = 1;
  r.iterations[0].push = PushReport{true, 3, {3, 5}, 1.5, {}, 0.01};
  std::ostringstream out;
  ReplicationResult with_change = r;
  v1::ChangeEvidence& e = with_change.iterations[0].change.emplace();
  e.set_target_points(120), e.set_supported_points(20), e.set_vacated_points(90);
  e.set_occluded_points(4), e.set_elapsed_ms(12.5);
  e.set_object_supervoxels(3), e.set_object_points(400), e.set_object_supported_points(250);
  e.set_object_vacated_points(130), e.set_object_occluded_points(4);
  e.set_vacated_beyond_motion_points(70), e.set_object_vacated_beyond_motion_points(110);
  e.set_object_motion_fitted(true), e.set_object_motion_translation_m(0.034);
  e.set_carried_supported_points(10), e.set_carried_vacated_points(80);
  e.set_carried_occluded_points(2);
  with_change.iterations[0].displacement = SupervoxelDisplacement{114, 60};
  with_change.iterations[0].moved_learned = 5, with_change.iterations[0].moved_mislabelled = 1;
  with_change.iterations[0].objects_left_out = 2;
  std::ostringstream changed;
  WriteIterationCsv(with_change, changed);
  EXPECT_EQ(Lines(changed.str())[1].substr(Lines(changed.str())[1].rfind("100.000")),
            "100.000,120,20,90,4,12.500,114,60,1,3,400,250,130,4,70,110,1,0.034,10,80,2,5,1,2");
  WriteIterationCsv(r, out);
  const std::vector<std::string> lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], kIterationCsvHeader);
  EXPECT_EQ(lines[1],
            "1,300,17,1,0,1,0.5,1,0.75,,0.25,0.5,3,4,1,2,1,3,1,2,1.5,"
            "0.000,0.000,60.000,0.000,0.000,0.000,0.000,0.000,100.000,,,,,,,,,,,,,,,,,,,,,0,0,0");
  // No target: no label, no truth, no push; an undefined accuracy is empty too.
  EXPECT_EQ(lines[2],
            "2,300,,,,0,0.5,1,,,0.25,0.5,3,4,1,2,,,,,,"
            "0.000,0.000,60.000,0.000,0.000,0.000,0.000,0.000,100.000,,,,,,,,,,,,,,,,,,,,,0,0,0");
}

TEST(SummaryJson, CountsTheFailedRunsAndSpreadsTheFinalScores) {
  ExperimentOptions options;
  options.scene = "AnalyticScene";
  options.iterations = 2;
  options.replications = 3;
  const std::vector<ReplicationResult> runs = {
      Replication(0, {0.4, 0.9}), Replication(1, {0.9, 0.5}), Replication(2, {0.5, 0.7})};
  const std::string json = SummaryJson(options, {"127.0.0.1:1", true, 2.5}, runs);
  // Final thresholded accuracies 0.9, 0.5, 0.7: mean 0.7, one below 0.6.
  EXPECT_NE(json.find("\"failed_runs\": 1"), std::string::npos) << json;
  EXPECT_NE(json.find("\"accuracy\": {\n        \"mean\": 0.7,\n        \"min\": 0.5,\n"
                      "        \"max\": 0.9"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"iteration_order\": \"capture, ComputeMaps, score"), std::string::npos);
  EXPECT_NE(json.find("\"session_id\": \"s2\""), std::string::npos);
  EXPECT_NE(json.find("\"objects_left_out\": 0"), std::string::npos);
  EXPECT_NE(json.find("\"iteration\": 100"), std::string::npos);    // mean iteration time
  EXPECT_NE(json.find("\"compute_maps\": 60"), std::string::npos);  // its breakdown
  // The soft precision is undefined in every replication: null, not a number.
  EXPECT_NE(json.find("\"precision\": null"), std::string::npos);
}

TEST(SummaryJson, AReplicationThatStoppedEarlyIsNotCountedInTheFinalScores) {
  ExperimentOptions options;
  options.iterations = 2;
  std::vector<ReplicationResult> runs = {Replication(0, {0.4, 0.9}), Replication(1, {0.3})};
  runs[1].error = "replication 1, iteration 2: ComputeMaps: unavailable";
  const std::string json = SummaryJson(options, {}, runs);
  EXPECT_NE(json.find("\"replications_counted\": 1"), std::string::npos) << json;
  EXPECT_NE(json.find("\"stopped_early\": 1"), std::string::npos);
  EXPECT_NE(json.find("\"failed\": null"), std::string::npos);
  EXPECT_NE(json.find("\"failed_runs\": 0"), std::string::npos);
}

TEST(EnvelopeOver, MeanMinAndMaxOfTheDefinedValuesPerIteration) {
  const std::vector<ReplicationResult> runs = {Replication(0, {0.2, std::nullopt, 0.6}),
                                               Replication(1, {0.4, std::nullopt}),
                                               Replication(2, {0.9, std::nullopt, 1.0})};
  const Envelope e =
      EnvelopeOver(runs, [](const IterationRecord& i) { return i.thresholded.accuracy; });
  // Iteration 2 has no defined value anywhere: left out of the curve.
  EXPECT_EQ(e.x, (std::vector<double>{1, 3}));
  ASSERT_EQ(e.mean.size(), 2u);
  EXPECT_DOUBLE_EQ(e.mean[0], 0.5);  // (0.2 + 0.4 + 0.9) / 3
  EXPECT_DOUBLE_EQ(e.mean[1], 0.8);  // (0.6 + 1.0) / 2: replication 1 stopped
  EXPECT_EQ(e.low, (std::vector<double>{0.2, 0.6}));
  EXPECT_EQ(e.high, (std::vector<double>{0.9, 1.0}));
}

}  // namespace
}  // namespace relmap::sim
