// relmap-sim run: options, the scene check, the server (given or started), the
// experiment, and a few lines of results on standard error.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include "experiment.h"
#include "local_server.h"
#include "scene_loading.h"
#include "server_binary.h"
#include "sim_commands.h"
#include "spread.h"

namespace relmap::sim {
namespace {

int Fail(int code, const std::string& message) {
  std::fprintf(stderr, "relmap-sim run: %s\n", message.c_str());
  return code;
}

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
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h") {
      std::fputs(kRunUsage, stdout);
      return 0;
    }
  }
  StatusOr<ExperimentOptions> options = ParseExperimentOptions(argc, argv, 1);
  if (!options.ok()) {
    std::fprintf(stderr, "relmap-sim run: %s\n%s", options.status().message().c_str(), kRunUsage);
    return 2;
  }
  // The scene first: a bad name or file is found before a server starts.
  if (StatusOr<std::unique_ptr<SimulatedScene>> scene = LoadOdeScene(options->scene, options->seed);
      !scene.ok()) {
    return Fail(scene.status().code() == StatusCode::kUnimplemented ? 1 : 2,
                scene.status().message());
  }
  std::error_code error;
  std::filesystem::create_directories(options->out, error);
  if (error) return Fail(2, "cannot create " + options->out + ": " + error.message());

  std::unique_ptr<client::LocalServer> launched;
  std::string address = options->server;
  if (address.empty()) {
    StatusOr<std::string> binary = FindServerBinary(options->server_binary);
    if (!binary.ok()) return Fail(2, binary.status().message());
    client::LocalServerOptions server_options;
    server_options.log_path = options->out + "/server.log";
    StatusOr<std::unique_ptr<client::LocalServer>> started =
        client::LocalServer::Start(*binary, server_options);
    if (!started.ok()) return Fail(1, started.status().message());
    launched = std::move(*started);
    address = launched->address();
    std::fprintf(stderr, "relmap-sim run: started %s on %s (log in %s/server.log)\n",
                 binary->c_str(), address.c_str(), options->out.c_str());
  }
  client::ClientOptions client_options;
  client_options.address = address;
  client::RelevanceClient client(client_options);
  if (const char* key = std::getenv("RELMAP_ADMIN_KEY"); key != nullptr && *key != '\0') {
    client.set_admin_key(key);
  }
  StatusOr<ExperimentRun> run =
      RunExperiment(*options, LoadOdeScene, client, address, launched != nullptr, stderr);
  if (!run.ok()) return Fail(1, run.status().message());
  PrintResults(*options, *run);
  for (const ReplicationResult& r : run->replications) {
    if (!r.error.empty()) return 1;
  }
  return 0;
}

}  // namespace relmap::sim
