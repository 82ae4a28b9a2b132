// A sampler thread reads /proc once a second while the rounds run on the calling thread.
#include "soak.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <fstream>
#include <limits>
#include <mutex>
#include <thread>

#include "common/image/line_plot.h"
#include "common/random.h"
#include "load_sessions.h"
#include "process_memory.h"

namespace relmap::load {
namespace {

using Clock = std::chrono::steady_clock;

double MiB(std::int64_t kib) { return static_cast<double>(kib) / 1024.0; }

// Samples the server's RSS every second into `samples`, tagged with the phase it is told.
class MemorySampler {
 public:
  MemorySampler(pid_t pid, Clock::time_point start) : pid_(pid), start_(start) {
    thread_ = std::thread([this] { Loop(); });
  }
  MemorySampler(const MemorySampler&) = delete;
  MemorySampler& operator=(const MemorySampler&) = delete;
  ~MemorySampler() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }

  void SetPhase(int round, bool rest) {
    std::lock_guard lock(mutex_);
    round_ = round;
    rest_ = rest;
  }

  std::vector<MemorySample> Samples() const {
    std::lock_guard lock(mutex_);
    return samples_;
  }

 private:
  void Loop() {
    std::unique_lock lock(mutex_);
    auto next = Clock::now();
    while (!stop_) {
      lock.unlock();
      const StatusOr<ProcessMemory> memory = ReadProcessMemory(pid_);
      lock.lock();
      if (memory.ok()) {
        samples_.push_back({std::chrono::duration<double>(Clock::now() - start_).count(),
                            MiB(memory->rss_kib), round_, rest_});
      }
      next += std::chrono::seconds(1);
      wake_.wait_until(lock, next, [this] { return stop_; });
    }
  }

  const pid_t pid_;
  const Clock::time_point start_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  int round_ = 0;
  bool rest_ = false;
  std::vector<MemorySample> samples_;
  std::thread thread_;
};

StatusOr<double> RssMiB(pid_t pid) {
  const StatusOr<ProcessMemory> memory = ReadProcessMemory(pid);
  if (!memory.ok()) return memory.status();
  return MiB(memory->rss_kib);
}

}  // namespace

StatusOr<SoakResults> RunSoak(client::RelevanceClient& client, pid_t server_pid,
                              const LoadCloud& cloud, const SoakPlan& plan,
                              const std::function<void(const std::string&)>& progress) {
  SoakResults results;
  const StatusOr<double> baseline = RssMiB(server_pid);
  if (!baseline.ok()) return baseline.status();
  results.baseline_rss_mib = *baseline;
  const Clock::time_point start = Clock::now();
  MemorySampler sampler(server_pid, start);
  Random seeds(plan.seed);
  for (int round = 1; round <= plan.rounds; ++round) {
    sampler.SetPhase(round, false);
    auto sessions = CreateLoadSessions(client, plan.sessions, seeds);
    if (!sessions.ok()) return sessions.status();
    const LoadResults load =
        RunLoad(client.stub(), *sessions, cloud, plan.load, [&](const LoadProgress& p) {
          char line[160];
          std::snprintf(line, sizeof line, "round %d/%d: %.0f s, %llu cycles", round, plan.rounds,
                        p.elapsed_seconds, static_cast<unsigned long long>(p.cycles));
          progress(line);
        });
    DeleteLoadSessions(client, *sessions);
    sampler.SetPhase(round, true);
    std::this_thread::sleep_for(std::chrono::duration<double>(plan.rest_seconds));
    SoakRound summary;
    summary.cycles = load.cycles;
    summary.failed_sessions = load.failed_sessions;
    if (results.first_failure.empty()) results.first_failure = load.first_failure;
    const StatusOr<double> rested = RssMiB(server_pid);
    if (!rested.ok()) return rested.status();
    summary.rested_rss_mib = *rested;
    for (const MemorySample& s : sampler.Samples()) {
      if (s.round == round && !s.rest)
        summary.peak_rss_mib = std::max(summary.peak_rss_mib, s.rss_mib);
    }
    results.rounds.push_back(summary);
    progress("round " + std::to_string(round) + ": peak " + std::to_string(summary.peak_rss_mib) +
             " MiB, after deleting its sessions " + std::to_string(summary.rested_rss_mib) +
             " MiB");
  }
  results.samples = sampler.Samples();
  return results;
}

Status WriteSoakCsv(const SoakResults& results, const std::string& path) {
  std::ofstream out(path);
  if (!out) return NotFoundError("cannot write " + path);
  out << "seconds,rss_mib,round,phase\n";
  for (const MemorySample& s : results.samples) {
    out << s.seconds << ',' << s.rss_mib << ',' << s.round << ',' << (s.rest ? "rest" : "load")
        << '\n';
  }
  return out ? OkStatus() : InternalError("writing " + path + " failed");
}

Status WriteSoakPlot(const SoakResults& results, const std::string& title,
                     const std::string& path) {
  image::Series load{"sessions under load", image::SeriesColour(0), {}, {}, {}, {}};
  image::Series rest{"after deleting them", image::SeriesColour(1), {}, {}, {}, {}};
  const MemorySample* previous = nullptr;
  for (const MemorySample& s : results.samples) {
    image::Series& series = s.rest ? rest : load;
    if (previous != nullptr && (previous->rest != s.rest || previous->round != s.round)) {
      // A gap (not finite) between the phases of one series.
      series.x.push_back(s.seconds / 60.0);
      series.y.push_back(std::numeric_limits<double>::quiet_NaN());
    }
    series.x.push_back(s.seconds / 60.0);
    series.y.push_back(s.rss_mib);
    previous = &s;
  }
  image::PlotOptions options;
  options.title = title;
  options.x_label = "minutes";
  options.y_label = "server RSS (MiB)";
  options.y_min = 0;
  return image::WritePng(image::RenderLinePlot(options, {load, rest}), path);
}

}  // namespace relmap::load
