// relmap-sim dataset: options, the scene, the server (given or started), one session
// that only computes maps, the frames, then the two files and a summary on stderr; with
// --mode physical, a physical-mode replication and what its session learned instead.
#include <chrono>
#include <cstdio>
#include <string>

#include "dataset_csv.h"
#include "dataset_frame.h"
#include "dataset_options.h"
#include "flags.h"
#include "grpc_status.h"
#include "physical_dataset.h"
#include "progress_bar.h"
#include "scene_loading.h"
#include "server_connection.h"
#include "sim_commands.h"

namespace relmap::sim {
namespace {

constexpr char kCommand[] = "relmap-sim dataset";

StatusOr<std::unique_ptr<SimulatedScene>> LoadScene(const DatasetOptions& options) {
  return LoadOdeSceneAt(options.scene, options.seed, options.resolution);
}

struct Collected {
  std::vector<DatasetRow> rows;
  std::size_t non_finite = 0;
  double server_ms = 0;
};

// Every frame in order, a progress line per tenth of them.
StatusOr<Collected> CollectFrames(const DatasetOptions& options, SimulatedScene& scene,
                                  client::RelevanceClient& client) {
  v1::SessionConfig config;
  config.set_seed(options.seed);
  client::SessionHandle session;
  if (Status created = client::FromGrpc(client.CreateSession(config, &session), "CreateSession");
      !created.ok()) {
    return created;
  }
  Collected collected;
  client::ProgressBar progress("frames", static_cast<std::uint64_t>(options.frames), stderr);
  Status status = OkStatus();
  for (int frame = 1; frame <= options.frames; ++frame) {
    StatusOr<LabelledFrame> labelled = LabelFrame(scene, client, session, options.seed, frame);
    if (!labelled.ok()) {
      status = Status(labelled.status().code(),
                      "frame " + std::to_string(frame) + ": " + labelled.status().message());
      break;
    }
    for (DatasetRow& row : labelled->rows) collected.rows.push_back(std::move(row));
    collected.non_finite += labelled->non_finite;
    collected.server_ms += labelled->server_ms;
    progress.Update(static_cast<std::uint64_t>(frame));
  }
  progress.Finish();
  // On a shared server the session and its cached frames would stay until they expire.
  client.DeleteSession(session);
  if (!status.ok()) return status;
  return collected;
}

// --mode physical: the run, its files and its summary line.
int RunPhysicalDataset(const DatasetOptions& options, SimulatedScene& scene,
                       client::RelevanceClient& client) {
  const auto start = std::chrono::steady_clock::now();
  StatusOr<std::vector<LearnedSample>> samples =
      CollectLearnedSamples(options, scene, client, stderr);
  if (!samples.ok()) return FailCommand("dataset", samples.status().message(), 1);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (Status written =
          WriteLearnedSamples(*samples, options.out, options.truth_out, options.frames_out);
      !written.ok()) {
    return FailCommand("dataset", written.message(), 2);
  }
  std::size_t moveable = 0, truly_moveable = 0, mislabelled = 0;
  for (const LearnedSample& s : *samples) {
    moveable += s.label ? 1 : 0;
    truly_moveable += s.truth ? 1 : 0;
    mislabelled += s.label != s.truth ? 1 : 0;
  }
  std::fprintf(stderr,
               "%s: %s, %d pushes in physical mode (seed %llu): %zu samples learned, %zu as "
               "moveable (%zu truly), %zu mislabelled; %.0f ms per push -> %s, %s%s%s\n",
               kCommand, scene.name().c_str(), options.frames,
               static_cast<unsigned long long>(options.seed), samples->size(), moveable,
               truly_moveable, mislabelled, 1000.0 * seconds / options.frames, options.out.c_str(),
               options.frames_out.c_str(), options.truth_out.empty() ? "" : ", ",
               options.truth_out.c_str());
  if (samples->empty()) return FailCommand("dataset", "no push was learned", 1);
  return 0;
}

}  // namespace

int RunDatasetCommand(int argc, char** argv) {
  if (WantsHelp(argc, argv, 1)) {
    std::fputs(kDatasetUsage, stdout);
    return 0;
  }
  StatusOr<DatasetOptions> options = ParseDatasetOptions(argc, argv, 1);
  if (!options.ok()) {
    std::fprintf(stderr, "%s: %s\n%s", kCommand, options.status().message().c_str(), kDatasetUsage);
    return 2;
  }
  StatusOr<std::unique_ptr<SimulatedScene>> scene = LoadScene(*options);
  if (!scene.ok()) {
    return FailCommand("dataset", scene.status().message(),
                       scene.status().code() == StatusCode::kUnimplemented ? 1 : 2);
  }
  client::LocalServerOptions server_options;
  server_options.memory_only = true;  // the session lives for this command only
  StatusOr<ServerConnection> server = ConnectOrStartServer(options->server, options->server_binary,
                                                           server_options, kCommand, stderr);
  if (!server.ok()) {
    return FailCommand("dataset", server.status().message(),
                       server.status().code() == StatusCode::kNotFound ? 2 : 1);
  }

  if (options->mode == LabellingMode::kPhysical) {
    return RunPhysicalDataset(*options, **scene, *server->client);
  }
  const auto start = std::chrono::steady_clock::now();
  StatusOr<Collected> collected = CollectFrames(*options, **scene, *server->client);
  if (!collected.ok()) return FailCommand("dataset", collected.status().message(), 1);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (Status written = WriteDataset(collected->rows, options->out, options->frames_out);
      !written.ok()) {
    return FailCommand("dataset", written.message(), 2);
  }
  std::size_t moveable = 0;
  for (const DatasetRow& row : collected->rows) moveable += row.moveable ? 1 : 0;
  std::fprintf(stderr,
               "%s: %s, %d frames (seed %llu): %zu rows, %zu moveable, %zu background; "
               "%zu supervoxels with non-finite features skipped; %.0f ms per frame "
               "(ComputeMaps %.0f ms in the server) -> %s, %s\n",
               kCommand, (*scene)->name().c_str(), options->frames,
               static_cast<unsigned long long>(options->seed), collected->rows.size(), moveable,
               collected->rows.size() - moveable, collected->non_finite,
               1000.0 * seconds / options->frames, collected->server_ms / options->frames,
               options->out.c_str(), options->frames_out.c_str());
  if (collected->rows.empty())
    return FailCommand("dataset", "no usable supervoxel in any frame", 1);
  return 0;
}

}  // namespace relmap::sim
