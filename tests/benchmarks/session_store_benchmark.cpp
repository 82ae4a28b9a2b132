// Benchmarks of the session stores on the machine's disk: one durable
// AppendSample (48-d) on SQLite with synchronous=FULL and NORMAL and on
// PostgreSQL (fsync on, synchronous_commit on), from 1 and 4 threads, and the
// save and load of the snapshot of a model trained on n = 1000 samples.
// Wall-clock times: an fsync costs no CPU. The PostgreSQL benchmarks need a
// server: RELMAP_BENCH_POSTGRES=postgresql://... (they are skipped without it).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>

#include "cmm/collaborative_mixture_models.h"
#include "datasets/synthetic_problems.h"
#include "session/records/snapshot_codec.h"
#include "session/store/postgres/postgres_session_store.h"
#include "session/store/sqlite/sqlite_session_store.h"

namespace relmap::session {
namespace {

constexpr int kDimension = 48;
using Synchronous = SqliteStoreOptions::Synchronous;

// A fresh database file; RELMAP_BENCH_DIR picks the disk (default: the system's
// temporary directory).
class ScratchDatabase {
 public:
  explicit ScratchDatabase(const std::string& name) {
    const char* base = std::getenv("RELMAP_BENCH_DIR");
    directory_ =
        std::filesystem::path(base != nullptr ? base : std::filesystem::temp_directory_path()) /
        std::string("relmap_store_bench_").append(name).append(std::to_string(getpid()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  ~ScratchDatabase() { std::filesystem::remove_all(directory_); }
  std::string path() const { return (directory_ / "sessions.db").string(); }

 private:
  std::filesystem::path directory_;
};

std::unique_ptr<SqliteSessionStore> OpenOrDie(const std::string& path, Synchronous synchronous) {
  SqliteStoreOptions options;
  options.synchronous = synchronous;
  auto store = SqliteSessionStore::Open(path, options);
  if (!store.ok()) std::abort();
  return std::move(store).value();
}

SessionRecord Record(const cmm::CmmConfig& config, const std::string& id = "bench") {
  SessionRecord record;
  record.id = id;
  record.token_hash = std::string(64, 'a');
  record.cmm_config = config;
  record.feature_dimension = kDimension;
  return record;
}

datasets::LabelledSamples Problem(int n) {
  datasets::ProblemOptions options;
  options.problem = datasets::Problem::kTwoMoons;
  options.samples = n;
  options.dimension = kDimension;
  return datasets::MakeProblem(options);
}

void BM_AppendSample(benchmark::State& state) {
  const auto synchronous = static_cast<Synchronous>(state.range(0));
  ScratchDatabase scratch("append");
  auto store = OpenOrDie(scratch.path(), synchronous);
  if (!store->CreateSession(Record(cmm::CmmConfig{})).ok()) std::abort();
  const datasets::LabelledSamples data = Problem(1000);
  int i = 0;
  for (auto _ : state) {
    const Eigen::VectorXd x = data.features.row(i % 1000).transpose();
    auto sequence =
        store->AppendSample("bench", std::string("r").append(std::to_string(i)),
                            std::span<const double>(x.data(), kDimension), data.labels[i % 1000]);
    if (!sequence.ok()) state.SkipWithError(sequence.status().message().c_str());
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(synchronous == Synchronous::kFull ? "synchronous=FULL" : "synchronous=NORMAL");
}
BENCHMARK(BM_AppendSample)
    ->Arg(static_cast<int>(Synchronous::kFull))
    ->Arg(static_cast<int>(Synchronous::kNormal))
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

// Appends from state.threads() threads, each to a session of its own, on one
// store shared by the threads (as the server's sessions share it).
void AppendFromThreads(benchmark::State& state, SessionStore& store) {
  static std::atomic<int> next_session{0};
  // The pid keeps ids apart across runs on one PostgreSQL database.
  const std::string session = std::string("bench-")
                                  .append(std::to_string(getpid()))
                                  .append("-")
                                  .append(std::to_string(next_session++));
  if (Status created = store.CreateSession(Record(cmm::CmmConfig{}, session)); !created.ok()) {
    state.SkipWithError(created.message().c_str());
    return;
  }
  const datasets::LabelledSamples data = Problem(1000);
  int i = 0;
  for (auto _ : state) {
    const Eigen::VectorXd x = data.features.row(i % 1000).transpose();
    auto sequence =
        store.AppendSample(session, std::string("r").append(std::to_string(i)),
                           std::span<const double>(x.data(), kDimension), data.labels[i % 1000]);
    if (!sequence.ok()) state.SkipWithError(sequence.status().message().c_str());
    ++i;
  }
  state.SetItemsProcessed(state.iterations());
}

// SQLite (synchronous=FULL), one connection under a mutex.
void BM_AppendSampleThreads(benchmark::State& state) {
  static ScratchDatabase scratch("threads");
  static std::unique_ptr<SqliteSessionStore> store = OpenOrDie(scratch.path(), Synchronous::kFull);
  AppendFromThreads(state, *store);
  state.SetLabel("sqlite synchronous=FULL");
}
BENCHMARK(BM_AppendSampleThreads)
    ->Threads(1)
    ->Threads(4)
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

// PostgreSQL with a pool of state.range(0) connections, one store per pool size.
void BM_PostgresAppendSample(benchmark::State& state) {
  const char* uri = std::getenv("RELMAP_BENCH_POSTGRES");
  if (uri == nullptr) {
    state.SkipWithError("RELMAP_BENCH_POSTGRES is not set");
    return;
  }
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<PostgresSessionStore>> stores;
  PostgresSessionStore* store = nullptr;
  {
    std::lock_guard lock(mutex);
    auto& slot = stores[static_cast<int>(state.range(0))];
    if (slot == nullptr) {
      PostgresStoreOptions options;
      options.max_connections = static_cast<int>(state.range(0));
      auto opened = PostgresSessionStore::Open(uri, options);
      if (!opened.ok()) {
        state.SkipWithError(opened.status().message().c_str());
        return;
      }
      slot = std::move(opened).value();
    }
    store = slot.get();
  }
  AppendFromThreads(state, *store);
  state.SetLabel("postgres, " + std::to_string(state.range(0)) + " connections");
}
BENCHMARK(BM_PostgresAppendSample)
    ->Args({1})
    ->Args({4})
    ->Threads(1)
    ->Threads(4)
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

// A store holding a session with n samples and a model trained on them; built
// once, since training at p = 48 takes seconds.
struct SnapshotFixture {
  static constexpr int kSamples = 1000;
  ScratchDatabase scratch{"snapshot"};
  std::unique_ptr<SqliteSessionStore> store;
  cmm::CmmSnapshot snapshot;

  SnapshotFixture() {
    const datasets::LabelledSamples data = Problem(kSamples);
    auto model = cmm::CollaborativeMixtureModels::Create(cmm::CmmConfig{}, kDimension).value();
    {
      auto filler = OpenOrDie(scratch.path(), Synchronous::kNormal);
      if (!filler->CreateSession(Record(model.config())).ok()) std::abort();
      for (int i = 0; i < kSamples; ++i) {
        const Eigen::VectorXd x = data.features.row(i).transpose();
        if (!model.Add(x, data.labels[i]).ok()) std::abort();
        if (!filler
                 ->AppendSample("bench", std::string("r").append(std::to_string(i)),
                                std::span<const double>(x.data(), kDimension), data.labels[i])
                 .ok()) {
          std::abort();
        }
      }
    }
    snapshot = model.Snapshot();
    store = OpenOrDie(scratch.path(), Synchronous::kFull);
  }
  static SnapshotFixture& Get() {
    static SnapshotFixture fixture;
    return fixture;
  }
};

void ReportSnapshotSize(benchmark::State& state, const cmm::CmmSnapshot& snapshot) {
  std::size_t components = 0;
  for (const auto& of_class : snapshot.components) components += of_class.size();
  state.counters["blob_bytes"] = static_cast<double>(EncodeSnapshot(snapshot)->size());
  state.counters["components"] = static_cast<double>(components);
}

void BM_SaveSnapshot(benchmark::State& state) {
  SnapshotFixture& f = SnapshotFixture::Get();
  for (auto _ : state) {
    const Status status = f.store->SaveSnapshot("bench", f.snapshot, SnapshotFixture::kSamples);
    if (!status.ok()) state.SkipWithError(status.message().c_str());
  }
  ReportSnapshotSize(state, f.snapshot);
}
BENCHMARK(BM_SaveSnapshot)->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_LoadLatestSnapshot(benchmark::State& state) {
  SnapshotFixture& f = SnapshotFixture::Get();
  if (!f.store->SaveSnapshot("bench", f.snapshot, SnapshotFixture::kSamples).ok()) std::abort();
  for (auto _ : state) {
    auto loaded = f.store->LoadLatestSnapshot("bench");
    if (!loaded.ok() || !loaded->has_value()) state.SkipWithError("load failed");
    benchmark::DoNotOptimize(loaded);
  }
  ReportSnapshotSize(state, f.snapshot);
}
BENCHMARK(BM_LoadLatestSnapshot)->UseRealTime()->Unit(benchmark::kMillisecond);

// Encoding and decoding alone: the CPU part of the two above.
void BM_EncodeDecodeSnapshot(benchmark::State& state) {
  SnapshotFixture& f = SnapshotFixture::Get();
  for (auto _ : state) {
    auto decoded = DecodeSnapshot(*EncodeSnapshot(f.snapshot));
    if (!decoded.ok()) state.SkipWithError(decoded.status().message().c_str());
    benchmark::DoNotOptimize(decoded);
  }
  ReportSnapshotSize(state, f.snapshot);
}
BENCHMARK(BM_EncodeDecodeSnapshot)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace relmap::session

BENCHMARK_MAIN();
