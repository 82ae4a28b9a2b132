// Starting, killing and restarting the servers of a chaos run.
#include "chaos/server_fleet.h"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "relevance_client.h"

namespace relmap::chaos {
namespace {

constexpr char kDatabase[] = "relmap";
// A session held by a live server is free this long after its last call there: short,
// so that a session nginx hands back to a restarted server moves soon (the cluster
// test's value).
constexpr char kLeaseSeconds[] = "2";
constexpr auto kServingWithin = std::chrono::seconds(60);

std::string LoopbackAddress(int port) { return "127.0.0.1:" + std::to_string(port); }

bool OnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream directories(path != nullptr ? path : "");
  for (std::string directory; std::getline(directories, directory, ':');) {
    directory += '/';
    directory += program;
    if (::access(directory.c_str(), X_OK) == 0) return true;
  }
  return false;
}

// Asks `address` for its health until it answers SERVING. A new client each time: a
// channel that found nobody listening waits out gRPC's reconnect backoff (1 s and
// more) before it tries again, which would be measured instead of the server.
Status WaitUntilServing(const std::string& address) {
  client::ClientOptions options;
  options.address = address;
  options.deadline = std::chrono::milliseconds(1000);
  options.retry.max_attempts = 1;
  const auto give_up = std::chrono::steady_clock::now() + kServingWithin;
  while (std::chrono::steady_clock::now() < give_up) {
    client::RelevanceClient client(options);
    grpc::health::v1::HealthCheckResponse health;
    if (client.CheckHealth("", &health).ok() &&
        health.status() == grpc::health::v1::HealthCheckResponse::SERVING) {
      return OkStatus();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return Status(StatusCode::kUnavailable, address + " was not SERVING within 60 s");
}

}  // namespace

StatusOr<std::unique_ptr<ServerFleet>> ServerFleet::Start(StoreKind kind,
                                                          const std::string& server_binary,
                                                          const std::string& directory) {
  std::unique_ptr<ServerFleet> fleet(new ServerFleet(kind, server_binary, directory));
  if (kind == StoreKind::kPostgres || kind == StoreKind::kCluster) {
    const testing::PostgresInstanceOptions postgres_options;
    if (::access((postgres_options.bin_directory + "/initdb").c_str(), X_OK) != 0) {
      return FailedPreconditionError("no PostgreSQL server programs in " +
                                     postgres_options.bin_directory);
    }
    if (kind == StoreKind::kCluster && !OnPath("nginx")) {
      return FailedPreconditionError("no nginx on the PATH");
    }
    auto postgres = testing::PostgresInstance::Start(postgres_options);
    if (!postgres.ok()) return postgres.status();
    fleet->postgres_ = std::move(postgres).value();
    if (Status created = fleet->postgres_->CreateDatabase(kDatabase); !created.ok()) return created;
  }
  fleet->servers_.resize(kind == StoreKind::kCluster ? 2 : 1);
  for (int i = 0; i < fleet->servers(); ++i) {
    fleet->servers_[static_cast<std::size_t>(i)].port = testing::FreeLoopbackPort();
    if (auto started = fleet->Restart(i); !started.ok()) return started.status();
  }
  if (kind == StoreKind::kCluster) {
    fleet->nginx_ = std::make_unique<testing::NginxProcess>(
        directory + "/nginx", std::vector<std::string>{LoopbackAddress(fleet->servers_[0].port),
                                                       LoopbackAddress(fleet->servers_[1].port)});
    if (!fleet->nginx_->Start()) {
      return Status(StatusCode::kUnavailable, "nginx did not start: " + fleet->nginx_->LogTail());
    }
  }
  return fleet;
}

ServerFleet::~ServerFleet() {
  nginx_.reset();
  servers_.clear();  // SIGTERM, then the directories of their port files go
}

std::string ServerFleet::address() const {
  return nginx_ != nullptr ? nginx_->address() : LoopbackAddress(servers_.front().port);
}

std::vector<std::string> ServerFleet::StoreArguments() const {
  switch (kind_) {
    case StoreKind::kSqlite:
      return {"--data-dir", directory_ + "/data"};
    case StoreKind::kPostgres:
    case StoreKind::kCluster:
      return {"--store", postgres_->Uri(kDatabase), "--lease-seconds", kLeaseSeconds};
    case StoreKind::kMemory:
      return {};
  }
  return {};
}

// A log line starts with its time, "[2026-12-03 08:16:18.448]", so that the later of
// two lines is the greater string.
int ServerFleet::LastServing(const std::string& session_id) const {
  const std::string mention = "session=" + session_id;
  int serving = -1;
  std::string latest;
  for (int i = 0; i < servers(); ++i) {
    const Server& server = servers_[static_cast<std::size_t>(i)];
    if (server.process == nullptr) continue;
    std::ifstream log(server.process->log_path());
    std::string last;
    for (std::string line; std::getline(log, line);) {
      if (line.find(mention) != std::string::npos) last = line.substr(0, line.find(']') + 1);
    }
    if (!last.empty() && last > latest) {
      latest = last;
      serving = i;
    }
  }
  return serving;
}

void ServerFleet::Kill(int i) {
  Server& server = servers_.at(static_cast<std::size_t>(i));
  if (server.process == nullptr) return;
  ::kill(server.process->pid(), SIGKILL);
  server.process.reset();  // reaps it (its SIGTERM finds it dead)
}

StatusOr<double> ServerFleet::Restart(int i) {
  Server& server = servers_.at(static_cast<std::size_t>(i));
  client::LocalServerOptions options;
  options.memory_only = true;  // the store is given below, the same at every start
  options.extra_arguments = StoreArguments();
  // The last --listen wins over LocalServer's port 0: the same port every time.
  options.extra_arguments.insert(options.extra_arguments.end(),
                                 {"--listen", LoopbackAddress(server.port)});
  options.log_path =
      directory_ + "/server" + std::to_string(i) + ".log." + std::to_string(server.starts++);
  const auto start = std::chrono::steady_clock::now();
  auto process = client::LocalServer::Start(server_binary_, options);
  if (!process.ok()) return process.status();
  server.process = std::move(process).value();
  if (Status serving = WaitUntilServing(LoopbackAddress(server.port)); !serving.ok()) {
    return serving;
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace relmap::chaos
