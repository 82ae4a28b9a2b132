// relmap-load: the load benchmark of the relevance server. S concurrent sessions,
// each looping ComputeMaps → PostOutcome on the async API, against one server on
// loopback that it starts with a temporary data directory (or a running one).
// Figures: throughput, client-observed latency percentiles, and the server's
// resident-memory growth per session. See --help.
#include <cstdio>
#include <exception>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/random.h"
#include "load_cloud.h"
#include "load_driver.h"
#include "load_options.h"
#include "load_report.h"
#include "load_sessions.h"
#include "local_server.h"
#include "process_memory.h"
#include "relevance_client.h"
#include "soak.h"
#include "synthetic_cloud.h"

namespace relmap::load {
namespace {

// Prints "relmap-load: <message>" and gives the exit code of a failed run.
int Failure(const std::string& message) {
  std::fprintf(stderr, "relmap-load: %s\n", message.c_str());
  return 2;
}

StatusOr<LoadCloud> LoadTheCloud(const LoadOptions& options) {
  if (!options.cloud_path.empty()) return ReadPcdCloud(options.cloud_path);
  return MakeSyntheticCloud(options.synthetic_width, options.synthetic_height);
}

// The server's memory, when its pid is known.
std::optional<ProcessMemory> MemoryOf(pid_t pid) {
  if (pid <= 0) return std::nullopt;
  StatusOr<ProcessMemory> memory = ReadProcessMemory(pid);
  if (!memory.ok()) {
    std::fprintf(stderr, "relmap-load: %s\n", memory.status().message().c_str());
    return std::nullopt;
  }
  return *memory;
}

void PrintProgress(const LoadProgress& progress) {
  const double rate = progress.elapsed_seconds > 0
                          ? static_cast<double>(progress.calls) / progress.elapsed_seconds
                          : 0.0;
  std::fprintf(stderr,
               "relmap-load: %6.1f s %5.1f%%  %llu cycles, %llu calls (%.1f/s), %llu "
               "RESOURCE_EXHAUSTED\n",
               progress.elapsed_seconds, 100.0 * progress.fraction_done,
               static_cast<unsigned long long>(progress.cycles),
               static_cast<unsigned long long>(progress.calls), rate,
               static_cast<unsigned long long>(progress.exhausted));
}

// The soak mode: prints its summary, writes the CSV and the plot, and checks the growth
// after the last rest.
int Soak(const LoadOptions& options, client::RelevanceClient& client, pid_t server_pid,
         const LoadCloud& cloud) {
  SoakPlan plan;
  plan.rounds = options.soak_rounds;
  plan.sessions = options.sessions;
  plan.rest_seconds = options.rest_seconds;
  plan.seed = options.seed;
  plan.load.cycles = options.cycles;
  plan.load.seconds = options.seconds;
  plan.load.deadline =
      std::chrono::milliseconds(static_cast<long long>(options.deadline_seconds * 1000));
  if (options.max_attempts > 0) plan.load.retry.max_attempts = options.max_attempts;
  StatusOr<SoakResults> soak = RunSoak(
      client, server_pid, cloud, plan,
      [](const std::string& line) { std::fprintf(stderr, "relmap-load: %s\n", line.c_str()); });
  if (!soak.ok()) return Failure(soak.status().message());
  std::printf("soak: %d rounds of %d sessions (%s), baseline RSS %.1f MiB\n", plan.rounds,
              plan.sessions, cloud.description.c_str(), soak->baseline_rss_mib);
  std::printf("round  cycles  peak RSS MiB  after deletion MiB\n");
  std::uint64_t failed = 0;
  for (std::size_t i = 0; i < soak->rounds.size(); ++i) {
    const SoakRound& r = soak->rounds[i];
    std::printf("%5zu  %6llu  %12.1f  %18.1f\n", i + 1, static_cast<unsigned long long>(r.cycles),
                r.peak_rss_mib, r.rested_rss_mib);
    failed += r.failed_sessions;
  }
  if (failed > 0)
    std::printf("failed sessions: %llu, first: %s\n", static_cast<unsigned long long>(failed),
                soak->first_failure.c_str());
  if (!options.csv_path.empty()) {
    if (Status written = WriteSoakCsv(*soak, options.csv_path); !written.ok()) {
      return Failure(written.message());
    }
  }
  if (!options.png_path.empty()) {
    const std::string title = "relmap-server RSS, " + std::to_string(plan.sessions) +
                              " sessions per round, " + cloud.description;
    if (Status written = WriteSoakPlot(*soak, title, options.png_path); !written.ok()) {
      return Failure(written.message());
    }
  }
  const double growth = soak->rounds.back().rested_rss_mib - soak->baseline_rss_mib;
  if (options.max_rested_growth_mib >= 0 && growth > options.max_rested_growth_mib) {
    std::printf("FAILED: %.1f MiB above the baseline after the last rest, more than %.1f\n", growth,
                options.max_rested_growth_mib);
    return 1;
  }
  return failed == 0 ? 0 : 1;
}

int Run(const LoadOptions& options) {
  StatusOr<LoadCloud> cloud = LoadTheCloud(options);
  if (!cloud.ok()) return Failure(cloud.status().message());

  LoadReport report;
  report.sessions = options.sessions;
  report.cycles_per_session = options.cycles;
  report.seconds_limit = options.seconds;
  report.seed = options.seed;
  report.cloud = cloud->description;

  std::unique_ptr<client::LocalServer> launched;
  std::string address = options.server_address;
  pid_t server_pid = options.server_pid;
  if (address.empty()) {
    client::LocalServerOptions server_options;
    server_options.memory_only = options.memory_only;
    if (options.server_max_threads > 0) {
      server_options.extra_arguments = {"--max-threads",
                                        std::to_string(options.server_max_threads)};
    }
    auto started = client::LocalServer::Start(options.server_binary, server_options);
    if (!started.ok()) return Failure(started.status().message());
    launched = std::move(started).value();
    address = launched->address();
    server_pid = launched->pid();
    report.server = options.server_binary;
    report.server_started = true;
    report.server_max_threads = options.server_max_threads;
    report.server_memory_only = options.memory_only;
  } else {
    report.server = "attached to " + address;
  }

  client::ClientOptions client_options;
  client_options.address = address;
  auto client = std::make_unique<client::RelevanceClient>(client_options);
  if (!options.admin_key_file.empty()) {
    std::string key;
    if (!(std::ifstream(options.admin_key_file) >> key)) {
      return Failure("cannot read an admin key from " + options.admin_key_file);
    }
    client->set_admin_key(key);
  }

  if (options.soak_rounds > 0) {
    if (server_pid <= 0) return Failure("a soak reads the server's memory: give --server-pid");
    const int status = Soak(options, *client, server_pid, *cloud);
    client.reset();
    if (launched) launched->Stop();
    return status;
  }

  report.before = MemoryOf(server_pid);
  // Session seeds are a stream of relmap::Random seeded by --seed: the same flags create the
  // same sessions, which then draw the same targets and learn the same labels.
  Random seeds(options.seed);
  auto created = CreateLoadSessions(*client, options.sessions, seeds);
  if (!created.ok()) return Failure(created.status().message() + " (server " + address + ")");
  const std::vector<LoadSession> sessions = std::move(created).value();
  report.after_sessions = MemoryOf(server_pid);

  LoadPlan plan;
  plan.cycles = options.cycles;
  plan.seconds = options.seconds;
  plan.deadline =
      std::chrono::milliseconds(static_cast<long long>(options.deadline_seconds * 1000));
  if (options.max_attempts > 0) plan.retry.max_attempts = options.max_attempts;
  report.results = RunLoad(client->stub(), sessions, *cloud, plan, PrintProgress);
  report.after_run = MemoryOf(server_pid);

  // Deleting the sessions separates what they hold from what the server keeps
  // anyway (allocator arenas, thread stacks): it frees their frame caches.
  DeleteLoadSessions(*client, sessions);
  report.after_delete = MemoryOf(server_pid);
  if (launched) {
    // The connection goes first: the server's graceful stop waits seconds for an
    // idle client connection to close.
    client.reset();
    launched->Stop();
  }
  if (options.json) {
    PrintJsonReport(stdout, report);
  } else {
    PrintTextReport(stdout, report);
  }
  return report.results.failed_sessions == 0 ? 0 : 1;
}

}  // namespace
}  // namespace relmap::load

int main(int argc, char** argv) {
  // The soak's sampler thread may fail to start (std::system_error).
  try {
    return relmap::load::Run(relmap::load::ParseLoadOptions(argc, argv, RELMAP_SERVER_BINARY));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "relmap-load: %s\n", error.what());
    return 2;
  }
}
