// Derived figures (rates, memory per session) and their two renderings.
#include "load_report.h"

#include <cmath>
#include <sstream>

#include "common/json_writer.h"

namespace relmap::load {
namespace {

double CallsPerSecond(const LoadReport& report) {
  const LoadResults& r = report.results;
  const auto calls = static_cast<double>(r.compute_maps_ms.count() + r.post_outcome_ms.count());
  return r.elapsed_seconds > 0 ? calls / r.elapsed_seconds : 0.0;
}

double CyclesPerSecond(const LoadReport& report) {
  const LoadResults& r = report.results;
  return r.elapsed_seconds > 0 ? static_cast<double>(r.cycles) / r.elapsed_seconds : 0.0;
}

// Growth of the server's resident memory from `before` to `after`, per session.
std::optional<double> KibPerSession(const LoadReport& report,
                                    const std::optional<ProcessMemory>& after) {
  if (!report.before || !after || report.sessions == 0) return std::nullopt;
  return static_cast<double>(after->rss_kib - report.before->rss_kib) / report.sessions;
}

std::string MaxThreadsText(const LoadReport& report) {
  return report.server_max_threads > 0 ? std::to_string(report.server_max_threads)
                                       : "server default";
}

std::string Mib(std::int64_t kib) {
  std::ostringstream text;
  text.precision(1);
  text << std::fixed << static_cast<double>(kib) / 1024.0 << " MiB";
  return text.str();
}

void PrintLatencyRow(std::FILE* out, const char* name, const LatencySummary& s) {
  std::fprintf(out, "  %-28s %7zu %9.1f %9.1f %9.1f %9.1f\n", name, s.count, s.p50, s.p99, s.mean,
               s.max);
}

// A JSON object written member by member.
class JsonObject {
 public:
  JsonObject& Number(const std::string& key, double value) {
    Key(key);
    if (std::isfinite(value)) {
      std::ostringstream number;
      number.precision(6);
      number << value;
      text_ += number.str();
    } else {
      text_ += "null";
    }
    return *this;
  }
  JsonObject& Optional(const std::string& key, const std::optional<double>& value) {
    return value ? Number(key, *value) : Raw(key, "null");
  }
  JsonObject& Boolean(const std::string& key, bool value) {
    return Raw(key, value ? "true" : "false");
  }
  JsonObject& String(const std::string& key, const std::string& value) {
    Key(key);
    text_ += client::JsonQuoted(value);
    return *this;
  }
  JsonObject& Raw(const std::string& key, const std::string& json) {
    Key(key);
    text_ += json;
    return *this;
  }
  std::string Close() const { return text_ + "}"; }

 private:
  void Key(const std::string& key) {
    text_ += text_.size() > 1 ? ",\"" : "\"";
    text_ += key + "\":";
  }
  std::string text_ = "{";
};

std::string LatencyJson(const LatencySummary& s) {
  return JsonObject()
      .Number("count", static_cast<double>(s.count))
      .Number("p50", s.p50)
      .Number("p99", s.p99)
      .Number("mean", s.mean)
      .Number("max", s.max)
      .Close();
}

std::string MemoryJson(const std::optional<ProcessMemory>& memory) {
  if (!memory) return "null";
  return JsonObject()
      .Number("rss_kib", static_cast<double>(memory->rss_kib))
      .Number("peak_rss_kib", static_cast<double>(memory->peak_rss_kib))
      .Close();
}

}  // namespace

void PrintTextReport(std::FILE* out, const LoadReport& report) {
  const LoadResults& r = report.results;
  std::ostringstream plan;
  plan << report.sessions << (report.sessions == 1 ? " session, " : " sessions, ");
  if (report.cycles_per_session > 0) plan << report.cycles_per_session << " cycles each";
  if (report.cycles_per_session > 0 && report.seconds_limit > 0) plan << " or ";
  if (report.seconds_limit > 0) plan << report.seconds_limit << " s";
  std::fprintf(out, "relmap-load: %s, %s, seed %llu\n", plan.str().c_str(), report.cloud.c_str(),
               static_cast<unsigned long long>(report.seed));
  if (report.server_started) {
    std::fprintf(out, "server: started %s (--max-threads %s, %s)\n", report.server.c_str(),
                 MaxThreadsText(report).c_str(),
                 report.server_memory_only ? "memory only" : "--data-dir in a temporary directory");
  } else {
    std::fprintf(out, "server: %s\n", report.server.c_str());
  }
  std::fprintf(out, "elapsed %.2f s: %llu cycles, %zu ComputeMaps, %zu PostOutcome\n",
               r.elapsed_seconds, static_cast<unsigned long long>(r.cycles),
               r.compute_maps_ms.count(), r.post_outcome_ms.count());
  std::fprintf(out, "throughput: %.2f calls/s (ComputeMaps + PostOutcome), %.2f cycles/s\n",
               CallsPerSecond(report), CyclesPerSecond(report));
  std::fprintf(out, "  %-28s %7s %9s %9s %9s %9s\n", "latency (ms)", "count", "p50", "p99", "mean",
               "max");
  PrintLatencyRow(out, "ComputeMaps (client)", r.compute_maps_ms.Summarise());
  PrintLatencyRow(out, "PostOutcome (client)", r.post_outcome_ms.Summarise());
  PrintLatencyRow(out, "push cycle (client)", r.cycle_ms.Summarise());
  PrintLatencyRow(out, "ComputeMaps (server handler)", r.server_compute_maps_ms.Summarise());
  const ServerStageMeans& stages = r.server_stages;
  std::fprintf(out,
               "server stages, mean ms: admission %.1f, decode %.1f, filter %.1f, supervoxels "
               "%.1f, features %.1f, maps %.1f; %.1f supervoxels per frame\n",
               stages.admission_ms, stages.decode_ms, stages.filter_ms, stages.supervoxels_ms,
               stages.features_ms, stages.maps_ms, r.mean_supervoxels);
  std::fprintf(out,
               "RESOURCE_EXHAUSTED (worker pool full), retried: %llu (ComputeMaps %llu, "
               "PostOutcome %llu)\n",
               static_cast<unsigned long long>(r.compute_maps_exhausted) + r.post_outcome_exhausted,
               static_cast<unsigned long long>(r.compute_maps_exhausted),
               static_cast<unsigned long long>(r.post_outcome_exhausted));
  std::fprintf(out, "labels posted: %llu moveable, %llu not moveable\n",
               static_cast<unsigned long long>(r.moveable_labels),
               static_cast<unsigned long long>(r.not_moveable_labels));
  if (report.before && report.after_sessions && report.after_run && report.after_delete) {
    std::fprintf(out,
                 "server RSS: %s before the sessions, %s after creating them, %s after the run "
                 "(peak %s), %s after deleting them\n",
                 Mib(report.before->rss_kib).c_str(), Mib(report.after_sessions->rss_kib).c_str(),
                 Mib(report.after_run->rss_kib).c_str(),
                 Mib(report.after_run->peak_rss_kib).c_str(),
                 Mib(report.after_delete->rss_kib).c_str());
    std::fprintf(out,
                 "server RSS growth per session: %.1f KiB after the run (creation alone %.1f KiB, "
                 "left after deleting them %.1f KiB)\n",
                 *KibPerSession(report, report.after_run),
                 *KibPerSession(report, report.after_sessions),
                 *KibPerSession(report, report.after_delete));
  } else {
    std::fprintf(out, "server RSS: unknown (no server pid)\n");
  }
  if (r.failed_sessions > 0) {
    std::fprintf(out, "FAILED sessions: %llu; first: %s\n",
                 static_cast<unsigned long long>(r.failed_sessions), r.first_failure.c_str());
  }
}

void PrintJsonReport(std::FILE* out, const LoadReport& report) {
  const LoadResults& r = report.results;
  const ServerStageMeans& s = r.server_stages;
  const std::string stages = JsonObject()
                                 .Number("admission", s.admission_ms)
                                 .Number("decode", s.decode_ms)
                                 .Number("filter", s.filter_ms)
                                 .Number("supervoxels", s.supervoxels_ms)
                                 .Number("features", s.features_ms)
                                 .Number("maps", s.maps_ms)
                                 .Close();
  JsonObject json;
  json.Number("sessions", report.sessions)
      .Number("cycles_per_session", static_cast<double>(report.cycles_per_session))
      .Number("seconds_limit", report.seconds_limit)
      .String("seed", std::to_string(report.seed))
      .String("cloud", report.cloud)
      .String("server", report.server)
      .Boolean("server_started", report.server_started)
      .String("server_max_threads", MaxThreadsText(report))
      .Boolean("server_memory_only", report.server_memory_only)
      .Number("elapsed_s", r.elapsed_seconds)
      .Number("cycles", static_cast<double>(r.cycles))
      .Number("calls_per_s", CallsPerSecond(report))
      .Number("cycles_per_s", CyclesPerSecond(report))
      .Raw("compute_maps_ms", LatencyJson(r.compute_maps_ms.Summarise()))
      .Raw("post_outcome_ms", LatencyJson(r.post_outcome_ms.Summarise()))
      .Raw("cycle_ms", LatencyJson(r.cycle_ms.Summarise()))
      .Raw("server_compute_maps_ms", LatencyJson(r.server_compute_maps_ms.Summarise()))
      .Raw("server_stage_mean_ms", stages)
      .Number("mean_supervoxels", r.mean_supervoxels)
      .Number("resource_exhausted_retries",
              static_cast<double>(r.compute_maps_exhausted + r.post_outcome_exhausted))
      .Number("resource_exhausted_compute_maps", static_cast<double>(r.compute_maps_exhausted))
      .Number("resource_exhausted_post_outcome", static_cast<double>(r.post_outcome_exhausted))
      .Number("moveable_labels", static_cast<double>(r.moveable_labels))
      .Number("not_moveable_labels", static_cast<double>(r.not_moveable_labels))
      .Raw("server_memory_before", MemoryJson(report.before))
      .Raw("server_memory_after_sessions", MemoryJson(report.after_sessions))
      .Raw("server_memory_after_run", MemoryJson(report.after_run))
      .Raw("server_memory_after_delete", MemoryJson(report.after_delete))
      .Optional("rss_growth_per_session_kib", KibPerSession(report, report.after_run))
      .Optional("rss_left_per_session_after_delete_kib", KibPerSession(report, report.after_delete))
      .Optional("rss_creation_per_session_kib", KibPerSession(report, report.after_sessions))
      .Number("failed_sessions", static_cast<double>(r.failed_sessions))
      .String("first_failure", r.first_failure);
  std::fprintf(out, "%s\n", json.Close().c_str());
}

}  // namespace relmap::load
