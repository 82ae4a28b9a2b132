// relmap-chaos: kill -9 of relmap-servers under concurrent sessions, then a check,
// through the API only, that every sample and outcome the servers acknowledged is
// stored exactly once. See --help, docs/reliability.md ("Chaos") for figures.
#include <spdlog/spdlog.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "benchmarks/load/synthetic_cloud.h"
#include "chaos/chaos_ledger.h"
#include "chaos/chaos_options.h"
#include "chaos/server_fleet.h"
#include "chaos/session_driver.h"
#include "common/command_line.h"
#include "common/random.h"

namespace relmap::chaos {
namespace {

constexpr int kExitSkipped = 77;  // CTest's SKIP_RETURN_CODE
using Clock = std::chrono::steady_clock;
using Drivers = std::vector<std::unique_ptr<SessionDriver>>;

const char* StoreName(StoreKind kind) {
  switch (kind) {
    case StoreKind::kSqlite:
      return "sqlite";
    case StoreKind::kPostgres:
      return "postgres";
    case StoreKind::kCluster:
      return "cluster";
    case StoreKind::kMemory:
      return "memory";
  }
  return "?";
}

std::string MakeDirectory(const ChaosOptions& options) {
  if (!options.directory.empty()) {
    std::filesystem::create_directories(options.directory);
    return options.directory;
  }
  std::string pattern = std::filesystem::temp_directory_path().string() + "/relmap-chaos-XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr) {
    tools::ExitWithError("relmap-chaos", "cannot create a directory like " + pattern);
  }
  // nginx's workers run unprivileged when this runs as root: they must enter it.
  ::chmod(pattern.c_str(), 0755);
  return pattern;
}

std::vector<std::uint64_t> WritesOf(const Drivers& drivers) {
  std::vector<std::uint64_t> writes;
  for (const auto& driver : drivers) writes.push_back(driver->acknowledged_writes());
  return writes;
}

std::uint64_t SamplesOf(const Drivers& drivers) {
  std::uint64_t samples = 0;
  for (const auto& driver : drivers) samples += driver->acknowledged_samples();
  return samples;
}

// Waits until every session has acknowledged `writes` writes more than `since`;
// false as soon as a session has stopped (it failed).
bool WaitForProgress(const Drivers& drivers, const std::vector<std::uint64_t>& since,
                     std::uint64_t writes) {
  for (;;) {
    bool all = true;
    for (std::size_t i = 0; i < drivers.size(); ++i) {
      if (!drivers[i]->running()) return false;
      all = all && drivers[i]->acknowledged_writes() >= since[i] + writes;
    }
    if (all) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// Waits (at most 2 s) until a session has a write on the wire; the sessions writing
// then (none if the wait ran out).
std::vector<const SessionDriver*> WaitForAWrite(const Drivers& drivers) {
  const Clock::time_point give_up = Clock::now() + std::chrono::seconds(2);
  for (;;) {
    std::vector<const SessionDriver*> writing;
    for (const auto& driver : drivers) {
      if (driver->writing()) writing.push_back(driver.get());
    }
    if (!writing.empty() || Clock::now() >= give_up) return writing;
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
}

// The server to kill: the one serving the first session caught writing (a cluster's
// servers each own some sessions), else each in turn.
int VictimOf(const ServerFleet& fleet, const std::vector<const SessionDriver*>& writing,
             int cycle) {
  if (!writing.empty()) {
    if (const int owner = fleet.LastServing(writing.front()->session().id); owner >= 0)
      return owner;
  }
  return (cycle - 1) % fleet.servers();
}

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// "min / median / max" of `values` in seconds, or "-" when there are none.
std::string Spread(std::vector<double> values) {
  if (values.empty()) return "-";
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  const double median = n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
  char text[96];
  std::snprintf(text, sizeof text, "%.2f / %.2f / %.2f s", values.front(), median, values.back());
  return text;
}

struct Figures {
  int cycles = 0;
  int writes_in_flight_at_kills = 0;
  std::vector<double> serving_seconds;        // restart to SERVING
  std::vector<double> writing_again_seconds;  // kill to every session acknowledging again
};

// The kill cycles. False when a session stopped or a server did not come back.
bool RunCycles(const ChaosOptions& options, ServerFleet& fleet, const Drivers& drivers,
               Figures& figures) {
  Random pauses(options.seed);
  for (int cycle = 1; cycle <= options.cycles; ++cycle) {
    if (!WaitForProgress(drivers, WritesOf(drivers),
                         static_cast<std::uint64_t>(options.writes_per_cycle))) {
      return false;
    }
    // A pause of up to 250 ms, so that the kills land at different points of the calls,
    // then the first moment a write is on the wire (a commit takes milliseconds, a
    // ComputeMaps tens of them: a kill at a random moment mostly meets maps).
    std::this_thread::sleep_for(std::chrono::microseconds(pauses.UniformIndex(250000)));
    const std::vector<const SessionDriver*> writing = WaitForAWrite(drivers);
    const int in_flight = static_cast<int>(writing.size());
    const int victim = VictimOf(fleet, writing, cycle);
    const std::vector<std::uint64_t> at_kill = WritesOf(drivers);
    const Clock::time_point killed = Clock::now();
    fleet.Kill(victim);
    const StatusOr<double> serving = fleet.Restart(victim);
    if (!serving.ok()) {
      spdlog::error("chaos cycle {}: server {} did not come back: {}", cycle, victim,
                    serving.status().message());
      return false;
    }
    figures.cycles = cycle;
    figures.writes_in_flight_at_kills += in_flight;
    figures.serving_seconds.push_back(*serving);
    if (!WaitForProgress(drivers, at_kill, 1)) return false;
    const double writing_again = SecondsSince(killed);
    figures.writing_again_seconds.push_back(writing_again);
    std::printf(
        "cycle %d/%d: kill -9 of server %d with %d of %zu sessions mid-write; it serves again "
        "%.2f s after its start, every session writing again %.2f s after the kill; "
        "%llu samples acknowledged so far\n",
        cycle, options.cycles, victim, in_flight, drivers.size(), *serving, writing_again,
        static_cast<unsigned long long>(SamplesOf(drivers)));
    std::fflush(stdout);
  }
  return WaitForProgress(drivers, WritesOf(drivers),
                         static_cast<std::uint64_t>(options.writes_per_cycle));
}

// Each session's exported samples against its ledger, after the writes ended.
LedgerCheck CheckSessions(const Drivers& drivers, int& failures) {
  LedgerCheck total;
  for (const auto& driver : drivers) {
    v1::ExportSessionResponse exported;
    const grpc::Status status = driver->client().ExportSession(driver->session(), &exported);
    if (status.error_code() == grpc::StatusCode::NOT_FOUND) {  // the session is gone
      std::printf("session %s: not found: every sample it was acknowledged is lost\n",
                  driver->session().id.c_str());
      total += driver->ledger().Check({});
      continue;
    }
    if (!status.ok()) {
      std::printf("session %s: ExportSession failed: %s\n", driver->session().id.c_str(),
                  status.error_message().c_str());
      ++failures;
      continue;
    }
    const LedgerCheck check = driver->ledger().Check(exported.state().samples());
    const std::uint64_t counted =
        exported.stats().moveable_samples() + exported.stats().non_moveable_samples();
    if (counted != check.stored) {
      std::printf("session %s: its counters say %llu samples, its export holds %llu\n",
                  driver->session().id.c_str(), static_cast<unsigned long long>(counted),
                  static_cast<unsigned long long>(check.stored));
      ++failures;
    }
    if (check.lost + check.duplicated + check.unexpected > 0) {
      std::printf(
          "session %s: %llu acknowledged, %llu stored: %llu lost, %llu duplicated, "
          "%llu stored though refused or never sent\n",
          driver->session().id.c_str(), static_cast<unsigned long long>(check.acknowledged),
          static_cast<unsigned long long>(check.stored),
          static_cast<unsigned long long>(check.lost),
          static_cast<unsigned long long>(check.duplicated),
          static_cast<unsigned long long>(check.unexpected));
    }
    total += check;
  }
  return total;
}

int Run(const ChaosOptions& options) {
  spdlog::set_level(spdlog::level::warn);
  const std::string directory = MakeDirectory(options);
  auto started = ServerFleet::Start(options.store, options.server_binary, directory);
  if (!started.ok()) {
    std::printf("relmap-chaos --store %s: %s\n", StoreName(options.store),
                started.status().message().c_str());
    if (started.status().code() == StatusCode::kFailedPrecondition) {
      std::printf("skipped: the %s store cannot run here\n", StoreName(options.store));
      if (options.directory.empty()) std::filesystem::remove_all(directory);
      return kExitSkipped;
    }
    std::printf("files kept in %s\n", directory.c_str());
    return 2;
  }
  ServerFleet& fleet = **started;
  std::printf("relmap-chaos: %s store, %d server(s) at %s, %d sessions, %d cycles; files in %s\n",
              StoreName(options.store), fleet.servers(), fleet.address().c_str(), options.sessions,
              options.cycles, directory.c_str());

  const v1::Cloud cloud = load::MakeSyntheticCloud(options.cloud_width, options.cloud_height).cloud;
  Drivers drivers;
  for (int i = 0; i < options.sessions; ++i) {
    DriverSettings settings;
    settings.address = fleet.address();
    settings.index = i;
    settings.seed = options.seed * 1000 + static_cast<std::uint64_t>(i);
    settings.samples_per_batch = options.samples_per_batch;
    drivers.push_back(std::make_unique<SessionDriver>(settings, cloud));
    if (Status created = drivers.back()->Start(); !created.ok()) {
      std::printf("session %d: %s\n", i, created.message().c_str());
      return 2;
    }
  }

  Figures figures;
  const bool completed = RunCycles(options, fleet, drivers, figures);
  for (const auto& driver : drivers) driver->Stop();
  int failures = 0;
  std::map<std::string, std::uint64_t> repeats;
  std::uint64_t refused = 0, unsettled = 0;
  for (const auto& driver : drivers) {
    if (!driver->failure().ok()) {
      std::printf("session %s stopped: %s\n", driver->session().id.c_str(),
                  driver->failure().message().c_str());
      ++failures;
    }
    for (const auto& [code, count] : driver->repeats()) repeats[code] += count;
    refused += driver->ledger().refused();
    unsettled += driver->ledger().unsettled();
  }
  if (!completed && failures == 0) ++failures;  // a server that did not come back

  // Every server killed once more and restarted, so that what is checked is what the
  // store kept, not what a server still held in memory.
  for (int i = 0; i < fleet.servers(); ++i) fleet.Kill(i);
  for (int i = 0; i < fleet.servers(); ++i) {
    if (const StatusOr<double> serving = fleet.Restart(i); !serving.ok()) {
      std::printf("server %d did not come back for the check: %s\n", i,
                  serving.status().message().c_str());
      return 1;
    }
  }
  const LedgerCheck check = CheckSessions(drivers, failures);

  std::printf("\nrelmap-chaos summary (%s store, %d sessions)\n", StoreName(options.store),
              options.sessions);
  std::printf("  kill -9 cycles             %d of %d (writes on the wire at the kills: %d)\n",
              figures.cycles, options.cycles, figures.writes_in_flight_at_kills);
  std::printf("  acknowledged               %llu samples and outcomes\n",
              static_cast<unsigned long long>(check.acknowledged));
  std::printf("  stored after a last kill   %llu\n", static_cast<unsigned long long>(check.stored));
  std::printf("  lost                       %llu\n", static_cast<unsigned long long>(check.lost));
  std::printf("  duplicated                 %llu\n",
              static_cast<unsigned long long>(check.duplicated));
  std::printf(
      "  stored, not acknowledged   %llu (outcomes refused as FRAME_GONE: %llu, "
      "writes given up: %llu)\n",
      static_cast<unsigned long long>(check.unexpected), static_cast<unsigned long long>(refused),
      static_cast<unsigned long long>(unsettled));
  std::printf("  restart to SERVING         %s (min / median / max)\n",
              Spread(figures.serving_seconds).c_str());
  std::printf("  kill to all writing again  %s\n", Spread(figures.writing_again_seconds).c_str());
  std::string repeated;
  for (const auto& [code, count] : repeats) {
    repeated += " " + code + "=" + std::to_string(count);
  }
  std::printf("  calls repeated by status  %s\n", repeated.empty() ? " none" : repeated.c_str());
  std::printf("  sessions failed            %d\n", failures);

  const bool clean =
      failures == 0 && check.lost == 0 && check.duplicated == 0 && check.unexpected == 0;
  drivers.clear();
  started->reset();
  // A run without a store is expected to fail; its files say nothing new.
  const bool keep = !clean && options.store != StoreKind::kMemory;
  if (!keep && options.directory.empty()) std::filesystem::remove_all(directory);
  if (keep) std::printf("files kept in %s\n", directory.c_str());
  return clean ? 0 : 1;
}

}  // namespace
}  // namespace relmap::chaos

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf("relmap-chaos", [&] {
    return relmap::chaos::Run(relmap::chaos::ParseChaosOptions(argc, argv, RELMAP_SERVER_BINARY));
  });
}
