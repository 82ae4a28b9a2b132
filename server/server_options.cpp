// Parsing and validation of relmap-server's settings.
#include "server_options.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "common/command_line.h"
#include "store_opening.h"

namespace relmap::server {
namespace {

constexpr std::string_view kUsage =
    "usage: relmap-server [--listen 127.0.0.1:50051] [--max-message-mb 64] [--max-sessions 1000]\n"
    "                     [--max-points 1228800] [--port-file PATH] [--data-dir DIR]\n"
    "                     [--admin-key-file PATH] [--tls-cert FILE --tls-key FILE]\n"
    "                     [--max-threads AUTO] [--metrics-listen 127.0.0.1:9464]\n"
    "                     [--metrics-port-file PATH] [--frames-per-session 8]\n"
    "                     [--max-concurrent-frames CORES] [--max-queued-frames AUTO]\n"
    "                     [--max-frame-wait-ms 60000]\n"
    "                     [--store sqlite:PATH|postgres://...] [--lease-seconds 10]\n"
    "                     [--drain-seconds 0] [--session-idle-expiry-seconds 0]\n"
    "  --listen      address to serve on; port 0 picks a free port\n"
    "  --port-file   write the port actually bound there (for tests and scripts)\n"
    "  --data-dir    keep sessions and samples in DIR/relmap.sqlite (WAL) and restore them\n"
    "                at start-up; without it (or --store) sessions live in memory only\n"
    "  --store       sqlite:PATH: the embedded store in one file (what --data-dir does);\n"
    "                postgres://USER@HOST:PORT/DB?...: a PostgreSQL database that several\n"
    "                servers share; each session is owned by one server at a time, any\n"
    "                other takes it over when the owner lets it go, dies or its lease ends\n"
    "  --lease-seconds  with PostgreSQL: how long a server's hold on a session outlives\n"
    "                its last call (default 10); a dead server's sessions are free at once\n"
    "  --drain-seconds  on SIGTERM, report NOT_SERVING on grpc.health.v1 and keep serving\n"
    "                this long before stopping (default 0; behind a load balancer: 5)\n"
    "  --admin-key-file  a file holding the admin key that create, list, delete and import need\n"
    "                (as 'x-relmap-admin-key' metadata); default $RELMAP_ADMIN_KEY, or none\n"
    "  --tls-cert, --tls-key  serve TLS with this PEM certificate chain and private key\n"
    "  --max-threads  bound of the worker threads; calls beyond it get RESOURCE_EXHAUSTED\n"
    "                (default: sized from the sessions in memory, a waiting place and a\n"
    "                thread for each, so that every robot is served in turn; with it the\n"
    "                pool is fixed)\n"
    "  --metrics-listen  serve Prometheus metrics at http://ADDR/metrics (IPv4 host:port)\n"
    "  --snapshot-every  with --data-dir: store a model snapshot every N samples of a\n"
    "                session, so a restart relearns at most N (default 500; 0 never)\n"
    "  --snapshot-after-learning-ms  with --data-dir: also one once the samples since the\n"
    "                last took this long to learn, so a restart relearns about that long\n"
    "                however large the session (default 500; 0 never)\n"
    "  --evict-idle-seconds  with --data-dir: drop sessions unused this long from memory;\n"
    "                they are loaded again on their next call (default 1800; 0 never)\n"
    "  --session-idle-expiry-seconds  delete sessions unused this long, from memory and\n"
    "                from the store, one log line each (default 0: sessions never end)\n"
    "  --frames-per-session  frames each session keeps for PostOutcome; an outcome on an\n"
    "                older one gets FAILED_PRECONDITION (default 8, at most 256)\n"
    "  --max-concurrent-frames  calls that process a cloud (ComputeMaps, PostOutcome with\n"
    "                an after cloud) running at once (default: the machine's cores)\n"
    "  --max-queued-frames  such calls waiting for a slot, in turn by session (default: the\n"
    "                sessions in memory + 2, at least 8, at most what a quarter of the RAM\n"
    "                holds at --max-message-mb each; half of --max-threads when that is\n"
    "                given); more\n"
    "                get RESOURCE_EXHAUSTED with a grpc-retry-pushback-ms trailer\n"
    "  --max-frame-wait-ms  the longest such a call waits for its turn before it is\n"
    "                refused; its deadline ends it sooner (default 60000, at most 600000)\n"
    "  --max-features-per-request  feature vectors in one ClassifyFeatures, AddSamples or\n"
    "                ImportSession (default 100000; more → RESOURCE_EXHAUSTED)\n"
    "  --config FILE  settings as lines 'name value' (the flag names without --)\n"
    "  Every setting can also come from RELMAP_<NAME> in the environment (e.g.\n"
    "  RELMAP_DATA_DIR); flags override the config file, which overrides the environment.\n";

// The flags that take a value; each can also come from a config file (a line
// "name value") or the environment (RELMAP_NAME, dashes as underscores).
constexpr std::string_view kSettings[] = {"listen",
                                          "max-message-mb",
                                          "max-sessions",
                                          "max-points",
                                          "port-file",
                                          "data-dir",
                                          "store",
                                          "lease-seconds",
                                          "drain-seconds",
                                          "tls-cert",
                                          "tls-key",
                                          "evict-idle-seconds",
                                          "session-idle-expiry-seconds",
                                          "snapshot-every",
                                          "snapshot-after-learning-ms",
                                          "metrics-listen",
                                          "metrics-port-file",
                                          "max-threads",
                                          "admin-key-file",
                                          "max-features-per-request",
                                          "frames-per-session",
                                          "max-concurrent-frames",
                                          "max-queued-frames",
                                          "max-frame-wait-ms"};

void Apply(ServerOptions& options, std::string_view name, const std::string& value) {
  using relmap::tools::ExitWithError;
  const auto number = [&] {
    return relmap::tools::ParseNumberOrExit("relmap-server", "--" + std::string(name),
                                            value.c_str());
  };
  if (name == "listen") {
    options.listen = value;
  } else if (name == "max-message-mb") {
    options.max_message_mb = static_cast<int>(number());
  } else if (name == "max-sessions") {
    options.max_sessions = static_cast<std::size_t>(number());
  } else if (name == "max-points") {
    options.max_points = static_cast<long long>(number());
  } else if (name == "port-file") {
    options.port_file = value;
  } else if (name == "data-dir") {
    options.data_dir = value;
  } else if (name == "store") {
    options.store = value;
  } else if (name == "lease-seconds") {
    options.lease_seconds = static_cast<long long>(number());
  } else if (name == "drain-seconds") {
    options.drain_seconds = static_cast<long long>(number());
  } else if (name == "tls-cert") {
    options.tls_cert = value;
  } else if (name == "tls-key") {
    options.tls_key = value;
  } else if (name == "evict-idle-seconds") {
    options.evict_idle_seconds = static_cast<long long>(number());
  } else if (name == "session-idle-expiry-seconds") {
    options.session_idle_expiry_seconds = static_cast<long long>(number());
  } else if (name == "max-concurrent-frames") {
    options.max_concurrent_frames = static_cast<std::size_t>(number());
  } else if (name == "max-queued-frames") {
    options.max_queued_frames = static_cast<std::size_t>(number());
  } else if (name == "max-frame-wait-ms") {
    options.max_frame_wait_ms = static_cast<long long>(number());
  } else if (name == "frames-per-session") {
    options.frames_per_session = static_cast<std::size_t>(number());
  } else if (name == "snapshot-every") {
    options.snapshot_every = static_cast<std::size_t>(number());
  } else if (name == "snapshot-after-learning-ms") {
    options.snapshot_after_learning_ms = static_cast<long long>(number());
  } else if (name == "metrics-listen") {
    options.metrics_listen = value;
  } else if (name == "metrics-port-file") {
    options.metrics_port_file = value;
  } else if (name == "max-threads") {
    options.max_threads = static_cast<int>(number());
  } else if (name == "max-features-per-request") {
    options.max_features_per_request = static_cast<std::size_t>(number());
  } else if (name == "admin-key-file") {
    std::ifstream in(value);
    if (!(in >> options.admin_key)) {
      ExitWithError("relmap-server", "cannot read an admin key from " + value);
    }
  } else {
    ExitWithError("relmap-server",
                  "unknown setting '" + std::string(name) + "'\n" + std::string(kUsage));
  }
}

// Settings in increasing precedence: environment, --config file, flags.
}  // namespace

ServerOptions ParseServerOptions(int argc, char** argv) {
  using relmap::tools::ExitWithError;
  ServerOptions options;
  for (std::string_view name : kSettings) {
    std::string variable = "RELMAP_" + std::string(name);
    for (char& c : variable)
      c = c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (const char* value = std::getenv(variable.c_str()); value != nullptr && *value != '\0') {
      Apply(options, name, value);
    }
  }
  if (const char* key = std::getenv("RELMAP_ADMIN_KEY"); key != nullptr) options.admin_key = key;

  std::vector<std::pair<std::string, std::string>> flags;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage.data(), stdout);
      std::exit(0);
    }
    if (!flag.starts_with("--") || i + 1 >= argc) {
      ExitWithError("relmap-server",
                    "bad argument '" + std::string(flag) + "'\n" + std::string(kUsage));
    }
    flags.emplace_back(std::string(flag.substr(2)), argv[++i]);
  }
  for (const auto& [name, value] : flags) {
    if (name != "config") continue;
    std::ifstream in(value);
    if (!in) ExitWithError("relmap-server", "cannot read the config file " + value);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      std::istringstream words(line.substr(0, line.find('#')));
      std::string key, setting;
      if (!(words >> key)) continue;  // blank or comment
      if (!(words >> setting)) {
        ExitWithError("relmap-server",
                      fmt::format("{}:{}: '{}' needs a value", value, number, key));
      }
      Apply(options, key, setting);
    }
  }
  for (const auto& [name, value] : flags) {
    if (name != "config") Apply(options, name, value);
  }

  if (options.tls_cert.empty() != options.tls_key.empty()) {
    ExitWithError("relmap-server", "--tls-cert and --tls-key go together");
  }
  if (options.max_threads != 0 && options.max_threads < 2) {
    ExitWithError("relmap-server", "--max-threads must be at least 2");
  }
  if (options.max_message_mb < 1 || options.max_sessions < 1 || options.max_points < 1 ||
      options.max_features_per_request < 1 || options.frames_per_session < 1) {
    ExitWithError("relmap-server", "limits must be positive");
  }
  if (!options.store.empty() && !options.data_dir.empty()) {
    ExitWithError("relmap-server", "--store and --data-dir are two names of one setting: give one");
  }
  if (!options.data_dir.empty()) options.store = "sqlite:" + options.data_dir + "/relmap.sqlite";
  if (!options.store.empty() && !IsStoreSpec(options.store)) {
    ExitWithError("relmap-server",
                  "--store must be sqlite:PATH or postgres://..., got '" + options.store + "'");
  }
  if (options.lease_seconds < 1) ExitWithError("relmap-server", "--lease-seconds must be >= 1");
  if (options.drain_seconds < 0) ExitWithError("relmap-server", "--drain-seconds must be >= 0");
  if (options.snapshot_after_learning_ms < 0) {
    ExitWithError("relmap-server", "--snapshot-after-learning-ms must be >= 0");
  }
  if (options.session_idle_expiry_seconds < 0) {
    ExitWithError("relmap-server", "--session-idle-expiry-seconds must be >= 0");
  }
  // A frame holds its cloud's supervoxels and features (up to max_points points each).
  if (options.frames_per_session > kMaxFramesPerSession) {
    ExitWithError("relmap-server", "--frames-per-session must lie in [1, " +
                                       std::to_string(kMaxFramesPerSession) + "]");
  }
  if (options.max_frame_wait_ms < 1 || options.max_frame_wait_ms > kMaxFrameWaitMs) {
    ExitWithError("relmap-server",
                  "--max-frame-wait-ms must lie in [1, " + std::to_string(kMaxFrameWaitMs) + "]");
  }
  if (options.max_concurrent_frames == 0) {
    options.max_concurrent_frames = std::max(1u, std::thread::hardware_concurrency());
  }
  if (options.max_queued_frames == 0 && options.max_threads != 0) {
    options.max_queued_frames = static_cast<std::size_t>(options.max_threads) / 2;
  }
  return options;
}

}  // namespace relmap::server
