// relmap-load: the load benchmark of the relevance server. S concurrent sessions,
// each looping ComputeMaps → PostOutcome on the async API, against one server on
// loopback that it starts with a temporary data directory (or a running one).
// Figures: throughput, client-observed latency percentiles, and the server's
// resident-memory growth per session. See --help.
#include <cstdio>
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
#include "local_server.h"
#include "process_memory.h"
#include "relevance_client.h"
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

// Deletes every session created so far (those with an id).
void DeleteSessions(client::RelevanceClient& client, const std::vector<LoadSession>& sessions) {
  for (const LoadSession& session : sessions) {
    if (session.handle.id.empty()) continue;
    if (const grpc::Status status = client.DeleteSession(session.handle); !status.ok()) {
      std::fprintf(stderr, "relmap-load: DeleteSession %s: %s\n", session.handle.id.c_str(),
                   status.error_message().c_str());
    }
  }
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

  report.before = MemoryOf(server_pid);
  // Session seeds are a stream of relmap::Random seeded by --seed: the same flags create the
  // same sessions, which then draw the same targets and learn the same labels.
  Random seeds(options.seed);
  std::vector<LoadSession> sessions(static_cast<std::size_t>(options.sessions));
  for (LoadSession& session : sessions) {
    session.seed = seeds.NextBits();
    v1::SessionConfig config;
    config.set_seed(session.seed);
    if (const grpc::Status status = client->CreateSession(config, &session.handle); !status.ok()) {
      DeleteSessions(*client, sessions);
      return Failure("CreateSession on " + address + ": " + status.error_message());
    }
  }
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
  DeleteSessions(*client, sessions);
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
  return relmap::load::Run(relmap::load::ParseLoadOptions(argc, argv, RELMAP_SERVER_BINARY));
}
