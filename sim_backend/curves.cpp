// Formatting only: every number here was measured by replication.cpp.
#include "curves.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <ostream>

#include "common/json_writer.h"
#include "replication.h"
#include "spread.h"

namespace relmap::sim {

const char kIterationCsvHeader[] =
    "iteration,supervoxels,target,label,truth,mislabelled,"
    "thresholded_precision,thresholded_recall,thresholded_accuracy,"
    "soft_precision,soft_recall,soft_accuracy,"
    "moveable_samples,non_moveable_samples,moveable_components,non_moveable_components,"
    "push_executed,push_target_body,push_target_moved,push_moved_bodies,push_simulated_s,"
    "respawn_ms,capture_ms,maps_ms,server_maps_ms,evaluation_ms,snapshot_ms,push_ms,outcome_ms,"
    "iteration_ms,change_target_points,change_supported_points,change_vacated_points,"
    "change_occluded_points,change_ms,push_target_points,push_displaced_points,"
    "push_target_displaced,change_object_supervoxels,change_object_points,"
    "change_object_supported_points,change_object_vacated_points,change_object_occluded_points,"
    "change_vacated_beyond_motion_points,change_object_vacated_beyond_motion_points,"
    "change_object_motion_fitted,change_object_motion_translation_m,"
    "change_carried_supported_points,change_carried_vacated_points,"
    "change_carried_occluded_points,moved_learned,moved_mislabelled,objects_left_out";

namespace {

using client::JsonWriter;

std::string Field(std::optional<double> value) {
  if (!value) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", *value);
  return text;
}

std::string Bit(std::optional<bool> value) {
  if (!value) return "";
  return *value ? "1" : "0";
}

std::string Milliseconds(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

void WriteScores(const metrics::Scores& scores, std::ostream& out) {
  out << ',' << Field(scores.precision) << ',' << Field(scores.recall) << ','
      << Field(scores.accuracy);
}

void WritePush(const std::optional<PushReport>& push, std::ostream& out) {
  if (!push) {
    out << ",,,,,";
    return;
  }
  const bool target_moved = std::find(push->moved_bodies.begin(), push->moved_bodies.end(),
                                      push->target_body) != push->moved_bodies.end();
  out << ',' << Bit(push->executed) << ',' << push->target_body << ',' << Bit(target_moved) << ','
      << push->moved_bodies.size() << ',' << Field(std::optional<double>(push->simulated_seconds));
}

const IterationRecord* LastOf(const ReplicationResult& r) {
  return r.iterations.empty() ? nullptr : &r.iterations.back();
}

bool RanToTheEnd(const ReplicationResult& r, const ExperimentOptions& options) {
  return r.error.empty() && static_cast<int>(r.iterations.size()) == options.iterations;
}

void WriteScoresJson(const metrics::Scores& scores, JsonWriter& json) {
  json.BeginObject()
      .Key("precision")
      .Number(scores.precision)
      .Key("recall")
      .Number(scores.recall)
      .Key("accuracy")
      .Number(scores.accuracy)
      .EndObject();
}

void WriteConfig(const ExperimentOptions& options, const RunFacts& facts, JsonWriter& json) {
  json.BeginObject();
  json.Key("scene").String(options.scene);
  json.Key("mode").String(ModeName(options.mode));
  json.Key("iterations").Integer(options.iterations);
  json.Key("replications").Integer(options.replications);
  json.Key("seed").Unsigned(options.seed);
  json.Key("server").String(facts.server);
  json.Key("server_started").Boolean(facts.server_started);
  json.Key("variant").String(VariantName(options.variant));
  json.Key("alpha").Number(options.alpha);
  json.Key("sampling").String(SamplingName(options.sampling));
  json.Key("labels").String(LabelScopeName(options.labels));
  json.Key("novelty").Boolean(options.novelty);
  json.Key("random_share").Number(options.random_share);
  json.Key("change_method").String(ChangeMethodName(options.change_method));
  json.Key("resolution");
  if (options.resolution) {
    json.String(std::to_string(options.resolution->width) + "x" +
                std::to_string(options.resolution->height));
  } else {
    json.Null();
  }
  json.Key("parallel").Integer(options.parallel);
  json.Key("snapshots").BeginArray();
  for (const int snapshot : options.snapshots) json.Integer(snapshot);
  json.EndArray().EndObject();
}

void WriteReplicationJson(const ReplicationResult& r, const ExperimentOptions& options,
                          JsonWriter& json) {
  const IterationRecord* last = LastOf(r);
  const auto skipped = std::count_if(r.iterations.begin(), r.iterations.end(),
                                     [](const IterationRecord& i) { return !i.label; });
  json.BeginObject();
  json.Key("replication").Integer(r.replication);
  json.Key("seed").Unsigned(r.seed);
  json.Key("session_id").String(r.session_id);
  json.Key("iterations_run").Unsigned(r.iterations.size());
  json.Key("error");
  if (r.error.empty()) {
    json.Null();
  } else {
    json.String(r.error);
  }
  json.Key("skipped_outcomes").Integer(skipped);
  json.Key("objects_left_out").Integer(ObjectsLeftOut(r));
  json.Key("final");
  if (last == nullptr) {
    json.Null();
  } else {
    json.BeginObject();
    json.Key("iteration").Integer(last->iteration);
    json.Key("thresholded_soft");
    WriteScoresJson(last->thresholded, json);
    json.Key("soft");
    WriteScoresJson(last->soft, json);
    json.Key("moveable_samples").Unsigned(last->model.moveable_samples);
    json.Key("non_moveable_samples").Unsigned(last->model.non_moveable_samples);
    json.Key("moveable_components").Integer(last->model.moveable_components);
    json.Key("non_moveable_components").Integer(last->model.non_moveable_components);
    json.Key("mislabelled").Unsigned(last->mislabelled);
    json.Key("moved_learned").Unsigned(last->moved_learned);
    json.Key("moved_mislabelled").Unsigned(last->moved_mislabelled);
    json.EndObject();
  }
  // Failed: ran to the end with a final thresholded accuracy below the bound; null
  // when it stopped early or its final accuracy is undefined.
  json.Key("failed");
  if (RanToTheEnd(r, options) && last->thresholded.accuracy) {
    json.Boolean(*last->thresholded.accuracy < kFailedRunAccuracy);
  } else {
    json.Null();
  }
  json.EndObject();
}

// Mean, min and max over `finished` of one final score.
void WriteFinalSpread(const std::vector<const IterationRecord*>& finished,
                      std::optional<double> metrics::Scores::*score,
                      metrics::Scores IterationRecord::*metric, JsonWriter& json) {
  std::vector<double> values;
  for (const IterationRecord* last : finished) {
    if (const std::optional<double> value = last->*metric.*score) values.push_back(*value);
  }
  const std::optional<Spread> spread = SpreadOf(values);
  if (!spread) {
    json.Null();
    return;
  }
  json.BeginObject()
      .Key("mean")
      .Number(spread->mean)
      .Key("min")
      .Number(spread->min)
      .Key("max")
      .Number(spread->max)
      .Key("defined_in")
      .Unsigned(values.size())
      .EndObject();
}

void WriteFinal(const std::vector<const IterationRecord*>& finished, JsonWriter& json) {
  using metrics::Scores;
  json.BeginObject();
  json.Key("replications_counted").Unsigned(finished.size());
  for (const auto& [name, metric] : {std::pair{"thresholded_soft", &IterationRecord::thresholded},
                                     std::pair{"soft", &IterationRecord::soft}}) {
    json.Key(name).BeginObject();
    for (const auto& [score_name, score] :
         {std::pair{"precision", &Scores::precision}, std::pair{"recall", &Scores::recall},
          std::pair{"accuracy", &Scores::accuracy}}) {
      json.Key(score_name);
      WriteFinalSpread(finished, score, metric, json);
    }
    json.EndObject();
  }
  json.EndObject();
}

// Means over every recorded iteration of every replication.
void WriteTimings(const std::vector<ReplicationResult>& replications, JsonWriter& json) {
  std::size_t count = 0;
  const IterationTimings mean = MeanTimings(replications, &count);
  json.BeginObject();
  json.Key("iterations_measured").Unsigned(count);
  json.Key("iteration").Number(mean.iteration_ms);
  json.Key("respawn").Number(mean.respawn_ms);
  json.Key("capture").Number(mean.capture_ms);
  json.Key("compute_maps").Number(mean.maps_ms);
  json.Key("compute_maps_in_server").Number(mean.server_maps_ms);
  json.Key("evaluation").Number(mean.evaluation_ms);
  json.Key("snapshots").Number(mean.snapshot_ms);
  json.Key("push").Number(mean.push_ms);
  json.Key("post_outcome").Number(mean.outcome_ms);
  json.EndObject();
}

}  // namespace

int ObjectsLeftOut(const ReplicationResult& r) {
  int total = 0;
  for (const IterationRecord& i : r.iterations) total += i.objects_left_out;
  return total;
}

void WriteIterationCsv(const ReplicationResult& replication, std::ostream& out) {
  out << kIterationCsvHeader << '\n';
  for (const IterationRecord& i : replication.iterations) {
    out << i.iteration << ',' << i.supervoxels << ',';
    if (i.target) out << *i.target;
    out << ',' << Bit(i.label) << ',' << Bit(i.truth) << ',' << i.mislabelled;
    WriteScores(i.thresholded, out);
    WriteScores(i.soft, out);
    out << ',' << i.model.moveable_samples << ',' << i.model.non_moveable_samples << ','
        << i.model.moveable_components << ',' << i.model.non_moveable_components;
    WritePush(i.push, out);
    const IterationTimings& t = i.timings;
    for (const double ms :
         {t.respawn_ms, t.capture_ms, t.maps_ms, t.server_maps_ms, t.evaluation_ms, t.snapshot_ms,
          t.push_ms, t.outcome_ms, t.iteration_ms}) {
      out << ',' << Milliseconds(ms);
    }
    if (i.change) {
      const v1::ChangeEvidence& c = *i.change;
      out << ',' << c.target_points() << ',' << c.supported_points() << ',' << c.vacated_points()
          << ',' << c.occluded_points() << ',' << Milliseconds(c.elapsed_ms());
    } else {
      out << ",,,,,";
    }
    if (i.displacement) {
      out << ',' << i.displacement->points << ',' << i.displacement->displaced << ','
          << Bit(i.displacement->moved());
    } else {
      out << ",,,";
    }
    if (i.change) {
      const v1::ChangeEvidence& c = *i.change;
      out << ',' << c.object_supervoxels() << ',' << c.object_points() << ','
          << c.object_supported_points() << ',' << c.object_vacated_points() << ','
          << c.object_occluded_points() << ',' << c.vacated_beyond_motion_points() << ','
          << c.object_vacated_beyond_motion_points() << ',' << Bit(c.object_motion_fitted()) << ','
          << Field(c.object_motion_fitted() ? std::optional<double>(c.object_motion_translation_m())
                                            : std::nullopt)
          << ',' << c.carried_supported_points() << ',' << c.carried_vacated_points() << ','
          << c.carried_occluded_points();
    } else {
      out << ",,,,,,,,,,,,";
    }
    out << ',' << i.moved_learned << ',' << i.moved_mislabelled << ',' << i.objects_left_out;
    out << '\n';
  }
}

std::string SummaryJson(const ExperimentOptions& options, const RunFacts& facts,
                        const std::vector<ReplicationResult>& replications) {
  std::vector<const IterationRecord*> finished;
  std::int64_t failed = 0, stopped_early = 0;
  for (const ReplicationResult& r : replications) {
    if (!RanToTheEnd(r, options)) {
      ++stopped_early;
      continue;
    }
    finished.push_back(LastOf(r));
    const std::optional<double>& accuracy = finished.back()->thresholded.accuracy;
    if (accuracy && *accuracy < kFailedRunAccuracy) ++failed;
  }
  JsonWriter json;
  json.BeginObject();
  json.Key("config");
  WriteConfig(options, facts, json);
  json.Key("iteration_order").String(kIterationOrder);
  json.Key("final_scores_are").String("those of the map computed at the last iteration");
  json.Key("elapsed_seconds").Number(facts.elapsed_seconds);
  json.Key("replications").BeginArray();
  for (const ReplicationResult& r : replications) WriteReplicationJson(r, options, json);
  json.EndArray();
  json.Key("final");
  WriteFinal(finished, json);
  json.Key("failed_run_accuracy_below").Number(kFailedRunAccuracy);
  json.Key("failed_runs").Integer(failed);
  json.Key("stopped_early").Integer(stopped_early);
  json.Key("mean_ms");
  WriteTimings(replications, json);
  json.EndObject();
  return json.Finish();
}

Status WriteRunFiles(const ExperimentOptions& options, const RunFacts& facts,
                     const std::vector<ReplicationResult>& replications) {
  const auto write = [](const std::string& path, const auto& fill) -> Status {
    std::ofstream out(path);
    fill(out);
    out.flush();
    if (!out) return InternalError("cannot write " + path);
    return OkStatus();
  };
  for (const ReplicationResult& r : replications) {
    const std::string path = options.out + "/replication-" + std::to_string(r.replication) + ".csv";
    Status written = write(path, [&](std::ostream& out) { WriteIterationCsv(r, out); });
    if (!written.ok()) return written;
  }
  return write(options.out + "/summary.json",
               [&](std::ostream& out) { out << SummaryJson(options, facts, replications); });
}

}  // namespace relmap::sim
