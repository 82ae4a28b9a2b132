// relmap-sim run: options, the scene check, the server (given or started), the
// experiment, and a few lines of results on standard error.
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

#include "curves.h"
#include "experiment.h"
#include "flags.h"
#include "scene_loading.h"
#include "server_connection.h"
#include "sim_commands.h"
#include "spread.h"

namespace relmap::sim {
namespace {

std::string Score(const std::optional<double>& value) {
  if (!value) return "undefined";
  char text[16];
  std::snprintf(text, sizeof text, "%.3f", *value);
  return text;
}

// Per replication its final thresholded-soft scores, then the mean time of an
// iteration and where it went.
void PrintResults(const ExperimentOptions& options, const ExperimentRun& run) {
  for (const ReplicationResult& r : run.replications) {
    if (!r.error.empty()) std::fprintf(stderr, "  error: %s\n", r.error.c_str());
    if (r.iterations.empty()) continue;
    const IterationRecord& last = r.iterations.back();
    std::fprintf(stderr,
                 "  replication %d (seed %llu): iteration %d, thresholded-soft accuracy %s, "
                 "precision %s, recall %s; soft accuracy %s\n",
                 r.replication, static_cast<unsigned long long>(r.seed), last.iteration,
                 Score(last.thresholded.accuracy).c_str(),
                 Score(last.thresholded.precision).c_str(), Score(last.thresholded.recall).c_str(),
                 Score(last.soft.accuracy).c_str());
    if (const int left_out = ObjectsLeftOut(r); left_out > 0) {
      std::fprintf(stderr, "    %d objects found no free pose and sat out their respawn\n",
                   left_out);
    }
  }
  std::size_t count = 0;
  const IterationTimings t = MeanTimings(run.replications, &count);
  if (count > 0) {
    std::fprintf(stderr,
                 "  mean iteration %.1f ms: respawn %.1f, capture %.1f, ComputeMaps %.1f, "
                 "evaluation %.1f, snapshots %.1f, push %.1f, PostOutcome %.1f\n",
                 t.iteration_ms, t.respawn_ms, t.capture_ms, t.maps_ms, t.evaluation_ms,
                 t.snapshot_ms, t.push_ms, t.outcome_ms);
  }
  std::fprintf(stderr, "relmap-sim run: %.1f s; results in %s (summary.json)\n",
               run.elapsed_seconds, options.out.c_str());
}

}  // namespace

int RunExperimentCommand(int argc, char** argv) {
  if (WantsHelp(argc, argv, 1)) {
    std::fputs(kRunUsage, stdout);
    return 0;
  }
  StatusOr<ExperimentOptions> options = ParseExperimentOptions(argc, argv, 1);
  if (!options.ok()) {
    std::fprintf(stderr, "relmap-sim run: %s\n%s", options.status().message().c_str(), kRunUsage);
    return 2;
  }
  // The scene first: a bad name or file is found before a server starts.
  const std::optional<ImageSize> resolution = options->resolution;
  const SceneFactory load = [resolution](const std::string& name_or_path, std::uint64_t seed) {
    return LoadOdeSceneAt(name_or_path, seed, resolution);
  };
  if (StatusOr<std::unique_ptr<SimulatedScene>> scene = load(options->scene, options->seed);
      !scene.ok()) {
    return FailCommand("run", scene.status().message(),
                       scene.status().code() == StatusCode::kUnimplemented ? 1 : 2);
  }
  std::error_code error;
  std::filesystem::create_directories(options->out, error);
  if (error) return FailCommand("run", "cannot create " + options->out + ": " + error.message(), 2);

  client::LocalServerOptions server_options;
  server_options.log_path = options->out + "/server.log";
  StatusOr<ServerConnection> server = ConnectOrStartServer(
      options->server, options->server_binary, server_options, "relmap-sim run", stderr);
  if (!server.ok()) {
    return FailCommand("run", server.status().message(),
                       server.status().code() == StatusCode::kNotFound ? 2 : 1);
  }
  StatusOr<ExperimentRun> run = RunExperiment(*options, load, *server->client, server->address,
                                              server->launched != nullptr, stderr);
  if (!run.ok()) return FailCommand("run", run.status().message(), 1);
  PrintResults(*options, *run);
  for (const ReplicationResult& r : run->replications) {
    if (!r.error.empty()) return 1;
  }
  return 0;
}

}  // namespace relmap::sim
