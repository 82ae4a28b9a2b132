// Replications are claimed from a shared counter by a fixed set of worker threads.
#include "experiment.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <thread>

#include "curves.h"
#include "plots.h"
#include "progress_bar.h"
#include "replication.h"

namespace relmap::sim {

StatusOr<ExperimentRun> RunExperiment(const ExperimentOptions& options,
                                      const SceneFactory& make_scene,
                                      client::RelevanceClient& client, const std::string& server,
                                      bool server_started, std::FILE* progress) {
  std::error_code error;
  std::filesystem::create_directories(options.out, error);
  if (error) return InternalError("cannot create " + options.out + ": " + error.message());

  const auto start = std::chrono::steady_clock::now();
  ExperimentRun run;
  run.replications.resize(static_cast<std::size_t>(options.replications));
  std::unique_ptr<client::ProgressBar> bar;
  if (progress != nullptr) {
    bar =
        std::make_unique<client::ProgressBar>("iterations",
                                              static_cast<std::uint64_t>(options.iterations) *
                                                  static_cast<std::uint64_t>(options.replications),
                                              progress);
  }
  std::mutex progress_mutex;
  std::uint64_t done = 0;
  const auto count_iteration = [&](const IterationRecord&) {
    if (!bar) return;
    const std::lock_guard lock(progress_mutex);
    bar->Update(++done);
  };

  std::atomic<int> next{0};
  const auto work = [&] {
    for (int r = next++; r < options.replications; r = next++) {
      ReplicationResult& result = run.replications[static_cast<std::size_t>(r)];
      StatusOr<std::unique_ptr<SimulatedScene>> scene =
          make_scene(options.scene, options.seed + static_cast<std::uint64_t>(r));
      if (!scene.ok()) {
        result.replication = r;
        result.seed = options.seed + static_cast<std::uint64_t>(r);
        result.error = "scene " + options.scene + ": " + scene.status().message();
        continue;
      }
      result = RunReplication(options, r, **scene, client, count_iteration);
    }
  };
  const int threads = std::min(options.parallel, options.replications);
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t) workers.emplace_back(work);
  work();
  for (std::thread& worker : workers) worker.join();
  if (bar) bar->Finish();
  run.elapsed_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  Status written =
      WriteRunFiles(options, {server, server_started, run.elapsed_seconds}, run.replications);
  if (!written.ok()) return written;
  written = WriteCurvePlots(run.replications, options.out);
  if (!written.ok()) return written;
  return run;
}

}  // namespace relmap::sim
