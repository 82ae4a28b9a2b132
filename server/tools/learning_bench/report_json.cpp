// Written with the client layer's JsonWriter, the one JSON writer of relmap's
// reports.
#include "learning_bench/report_json.h"

#include "common/json_writer.h"

namespace relmap::learning_bench {
namespace {

void Numbers(client::JsonWriter& json, std::string_view key, const std::vector<double>& values) {
  json.Key(key).BeginArray();
  for (const double v : values) json.Number(v);
  json.EndArray();
}

void Row(client::JsonWriter& json, const TableRow& r) {
  json.BeginObject();
  json.Key("stream").String(r.stream).Key("learner").String(r.learner);
  json.Key("replications").Integer(r.replications);
  json.Key("balanced_accuracy").BeginObject();
  json.Key("mean").Number(r.balanced_accuracy_mean).Key("min").Number(r.balanced_accuracy_min);
  json.EndObject();
  json.Key("soft_accuracy").Number(r.soft_accuracy);
  json.Key("log_loss").Number(r.log_loss).Key("brier").Number(r.brier);
  json.Key("components");
  if (r.components) {
    json.BeginArray().Number((*r.components)[0]).Number((*r.components)[1]).EndArray();
  } else {
    json.Null();
  }
  json.Key("update_us").BeginObject();
  json.Key("p50").Number(r.update_p50_us).Key("p99").Number(r.update_p99_us);
  json.EndObject();
  json.Key("predict_us").Number(r.predict_us);
  json.EndObject();
}

void LearnerOrNull(client::JsonWriter& json, std::string_view key,
                   const std::optional<TableRow>& row) {
  json.Key(key);
  if (row) {
    json.String(row->learner);
  } else {
    json.Null();
  }
}

}  // namespace

std::string ReportJson(const RunSettings& settings, const std::vector<TableRow>& rows,
                       const std::vector<StreamBest>& best,
                       const std::vector<CurveSummary>& curves) {
  client::JsonWriter json;
  json.BeginObject();
  json.Key("seed").Unsigned(settings.seed).Key("replications").Integer(settings.replications);
  json.Key("train_samples").Integer(settings.train_samples);
  json.Key("test_samples").Integer(settings.test_samples);
  json.Key("curve_every").Integer(settings.curve_every);
  json.Key("reference").String(settings.reference);
  json.Key("wall_seconds").Number(settings.wall_seconds);
  json.Key("rows").BeginArray();
  for (const TableRow& r : rows) Row(json, r);
  json.EndArray();
  json.Key("best").BeginObject();
  for (const StreamBest& b : best) {
    json.Key(b.stream).BeginObject();
    LearnerOrNull(json, "online", b.online);
    LearnerOrNull(json, "reference", b.reference);
    json.EndObject();
  }
  json.EndObject();
  json.Key("curves").BeginArray();
  for (const CurveSummary& c : curves) {
    json.BeginObject().Key("stream").String(c.stream).Key("learner").String(c.learner);
    Numbers(json, "samples", c.samples);
    Numbers(json, "mean", c.mean);
    Numbers(json, "min", c.min);
    Numbers(json, "max", c.max);
    json.EndObject();
  }
  json.EndArray();
  json.EndObject();
  return json.Finish();
}

}  // namespace relmap::learning_bench
