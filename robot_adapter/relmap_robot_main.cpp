// relmap-robot: connects a robot's camera and arm to a relmap server.
//   relmap-robot run --config robot.json|robot.yaml [--server ADDR] [--dry-run] [--max-pushes N]
//   relmap-robot replay RUN_DIR [--server ADDR]
// Without a server address (flag or config), a relmap-server is started on loopback
// for the command's duration.
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "common/command_line.h"
#include "directory_source.h"
#include "exec_driver.h"
#include "exploration_loop.h"
#include "local_server.h"
#include "openni2_source.h"
#include "replay.h"
#include "robot_config.h"
#include "server_binary.h"
#include "simulated_robot.h"
#include "stream_source.h"
#include "tcp_json_driver.h"

namespace relmap::robot {
namespace {

std::atomic<bool> g_stop{false};

extern "C" void OnStopSignal(int) { g_stop.store(true); }

void InstallStopHandlers() {
  struct sigaction action {};
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

// The usage on standard error with exit code 2 (a bad command line), or on standard
// output with 0 when asked for (--help).
int Usage(bool asked = false) {
  std::fprintf(asked ? stdout : stderr,
               "usage: relmap-robot run --config FILE [--server ADDR] [--dry-run] "
               "[--max-pushes N]\n"
               "       relmap-robot replay RUN_DIR [--server ADDR]\n");
  return asked ? 0 : 2;
}

int Fail(const Status& status) {
  std::fprintf(stderr, "relmap-robot: %s\n", status.message().c_str());
  return 1;
}

// The server to talk to: `address`, or a child started here (kept in `local`).
StatusOr<std::string> ServerAddress(const std::string& address,
                                    std::unique_ptr<client::LocalServer>* local) {
  if (!address.empty()) return address;
  StatusOr<std::string> binary = client::FindServerBinary("");
  if (!binary.ok()) return binary.status();
  StatusOr<std::unique_ptr<client::LocalServer>> started = client::LocalServer::Start(*binary);
  if (!started.ok()) return started.status();
  *local = std::move(started).value();
  std::fprintf(stderr, "relmap-robot: started %s at %s (its sessions end with this command)\n",
               binary->c_str(), (*local)->address().c_str());
  return (*local)->address();
}

std::unique_ptr<client::RelevanceClient> Connect(const std::string& address) {
  auto client = std::make_unique<client::RelevanceClient>(address);
  if (const char* key = std::getenv("RELMAP_ADMIN_KEY"); key != nullptr) client->set_admin_key(key);
  return client;
}

std::chrono::milliseconds Milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(seconds * 1000));
}

// The configured cloud source; the simulated robot, when it is one, into `simulated`.
StatusOr<std::unique_ptr<CloudSource>> MakeSource(const SourceConfig& config,
                                                  std::unique_ptr<SimulatedRobot>* simulated) {
  switch (config.kind_case()) {
    case SourceConfig::kSim: {
      StatusOr<std::unique_ptr<SimulatedRobot>> made = MakeSimulatedRobot(config.sim());
      if (!made.ok()) return made.status();
      *simulated = std::move(made).value();
      return (*simulated)->Source();
    }
    case SourceConfig::kStdin:
      return std::unique_ptr<CloudSource>(std::make_unique<StreamSource>(STDIN_FILENO, &g_stop));
    case SourceConfig::kTcp: {
      TcpSource::Options options;
      options.wait_timeout = Milliseconds(config.tcp().wait_timeout_seconds());
      StatusOr<std::unique_ptr<TcpSource>> listening =
          TcpSource::Listen(config.tcp().listen(), options, &g_stop);
      if (!listening.ok()) return listening.status();
      std::fprintf(stderr, "relmap-robot: waiting for PCD frames on %s (port %d)\n",
                   config.tcp().listen().c_str(), (*listening)->port());
      return std::unique_ptr<CloudSource>(std::move(listening).value());
    }
    case SourceConfig::kOpenni2: {
      OpenNI2Options options;
      options.device = config.openni2().device();
      options.frame_timeout = Milliseconds(config.openni2().frame_timeout_seconds());
      return OpenOpenNI2Source(options, &g_stop);
    }
    case SourceConfig::kDirectory:
    case SourceConfig::KIND_NOT_SET:
      break;
  }
  const DirectorySourceConfig& directory = config.directory();
  DirectorySource::Options options;
  options.wait_for_files = directory.wait_for_files();
  if (directory.has_poll_seconds()) options.poll = Milliseconds(directory.poll_seconds());
  options.wait_timeout = Milliseconds(directory.wait_timeout_seconds());
  return std::unique_ptr<CloudSource>(
      std::make_unique<DirectorySource>(directory.path(), options, &g_stop));
}

// The configured driver; the sim driver pushes in `simulated`'s scene (a sim driver
// comes with a sim source: ReadRobotConfig checks it).
std::unique_ptr<PusherDriver> MakeDriver(const RobotConfig& config, SimulatedRobot* simulated) {
  const DriverConfig& driver = config.driver();
  if (driver.has_sim()) return simulated->Driver();
  if (driver.has_tcp_json()) {
    return std::make_unique<TcpJsonDriver>(
        driver.tcp_json().address(), Milliseconds(driver.tcp_json().connect_timeout_seconds()),
        Milliseconds(driver.tcp_json().timeout_seconds()));
  }
  return std::make_unique<ExecDriver>(
      std::vector<std::string>(driver.exec().command().begin(), driver.exec().command().end()),
      Milliseconds(driver.exec().timeout_seconds()));
}

int Run(const std::vector<std::string>& args) {
  std::string config_path;
  std::string server;
  bool dry_run = false;
  long max_pushes = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const bool has_value = i + 1 < args.size();
    if (args[i] == "--config" && has_value) {
      config_path = args[++i];
    } else if (args[i] == "--server" && has_value) {
      server = args[++i];
    } else if (args[i] == "--max-pushes" && has_value) {
      max_pushes = std::strtol(args[++i].c_str(), nullptr, 10);
      if (max_pushes <= 0) return Usage();
    } else if (args[i] == "--dry-run") {
      dry_run = true;
    } else {
      return Usage();
    }
  }
  if (config_path.empty()) return Usage();
  StatusOr<RobotConfig> config = ReadRobotConfig(config_path);
  if (!config.ok()) return Fail(config.status());
  if (dry_run) config->set_dry_run(true);
  if (max_pushes > 0) config->set_max_pushes(static_cast<std::uint32_t>(max_pushes));
  if (server.empty()) server = config->server();

  std::unique_ptr<SimulatedRobot> simulated;
  StatusOr<std::unique_ptr<CloudSource>> source = MakeSource(config->source(), &simulated);
  if (!source.ok()) return Fail(source.status());
  std::unique_ptr<PusherDriver> driver = MakeDriver(*config, simulated.get());

  std::unique_ptr<client::LocalServer> local;
  StatusOr<std::string> address = ServerAddress(server, &local);
  if (!address.ok()) return Fail(address.status());
  const std::unique_ptr<client::RelevanceClient> client = Connect(*address);
  InstallStopHandlers();
  ExplorationLoop loop(*config, *client, **source, *driver, &g_stop);
  if (Status status = loop.Start(); !status.ok()) return Fail(status);
  std::fprintf(stderr, "relmap-robot: session %s, run %s%s\n", loop.session().id.c_str(),
               loop.run_id().c_str(), config->dry_run() ? " (dry run)" : "");
  StatusOr<RunSummary> summary = loop.Run();
  if (!summary.ok()) return Fail(summary.status());
  std::fprintf(stderr,
               "relmap-robot: %d iterations: %d posted, %d skipped, %d failed, %d dry-run; %d "
               "pushes%s\n",
               summary->iterations, summary->posted, summary->skipped, summary->failed,
               summary->dry_run, summary->pushes, summary->stopped ? "; stopped" : "");
  return 0;
}

int Replay(const std::vector<std::string>& args) {
  std::string run_dir;
  std::string server;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--server" && i + 1 < args.size()) {
      server = args[++i];
    } else if (run_dir.empty() && args[i].rfind("--", 0) != 0) {
      run_dir = args[i];
    } else {
      return Usage();
    }
  }
  if (run_dir.empty()) return Usage();
  std::unique_ptr<client::LocalServer> local;
  StatusOr<std::string> address = ServerAddress(server, &local);
  if (!address.ok()) return Fail(address.status());
  const std::unique_ptr<client::RelevanceClient> client = Connect(*address);
  StatusOr<ReplayResult> replayed = ReplayRun(run_dir, *client);
  if (!replayed.ok()) return Fail(replayed.status());
  // The learning curve, as CSV on stdout; the session on stderr.
  std::printf("iteration,supervoxel,label,accuracy\n");
  for (const ReplayedIteration& r : replayed->iterations) {
    std::printf("%d,%u,%s,", r.iteration, r.supervoxel,
                r.label == v1::LABEL_MOVEABLE ? "moved" : "still");
    if (r.accuracy) std::printf("%.4f", *r.accuracy);
    std::printf("\n");
  }
  std::fprintf(stderr, "relmap-robot: replayed %zu outcomes into session %s (token %s)\n",
               replayed->iterations.size(), replayed->session.id.c_str(),
               replayed->session.token.c_str());
  return 0;
}

}  // namespace
}  // namespace relmap::robot

namespace {

int Main(int argc, char** argv) {
  if (argc < 2) return relmap::robot::Usage();
  const std::string command = argv[1];
  if (command == "--help" || command == "-h") return relmap::robot::Usage(/*asked=*/true);
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (command == "run") return relmap::robot::Run(args);
  if (command == "replay") return relmap::robot::Replay(args);
  return relmap::robot::Usage();
}

}  // namespace

int main(int argc, char** argv) {
  return relmap::tools::ExitCodeOf("relmap-robot", [&] { return Main(argc, argv); });
}
