// relmap-server: the relevance server. Configuration by flags; gRPC health and
// reflection on; SIGTERM or SIGINT stop it gracefully (in-flight calls finish).
#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>
#include <grpcpp/resource_quota.h>
#include <signal.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "grpc/health/v1/health.pb.h"
#include "service/metrics_http.h"
#include "service/relevance_service.h"
#include "service/session_restore.h"
#include "session/credentials.h"
#include "session/session_registry.h"
#include "session/sqlite_session_store.h"
#include "tools/command_line.h"

namespace {

constexpr std::string_view kUsage =
    "usage: relmap-server [--listen 127.0.0.1:50051] [--max-message-mb 64] [--max-sessions 1000]\n"
    "                     [--max-points 1228800] [--port-file PATH] [--data-dir DIR]\n"
    "                     [--admin-key-file PATH] [--tls-cert FILE --tls-key FILE]\n"
    "                     [--max-threads 16] [--metrics-listen 127.0.0.1:9464]\n"
    "                     [--metrics-port-file PATH] [--frames-per-session 8]\n"
    "  --listen      address to serve on; port 0 picks a free port\n"
    "  --port-file   write the port actually bound there (for tests and scripts)\n"
    "  --data-dir    keep sessions and samples in DIR/relmap.sqlite (WAL) and restore them\n"
    "                at start-up; without it sessions live in memory only\n"
    "  --admin-key-file  a file holding the admin key that create, list and delete need\n"
    "                (as 'x-relmap-admin-key' metadata); default $RELMAP_ADMIN_KEY, or none\n"
    "  --tls-cert, --tls-key  serve TLS with this PEM certificate chain and private key\n"
    "  --max-threads  bound of the worker threads; calls beyond it get RESOURCE_EXHAUSTED\n"
    "  --metrics-listen  serve Prometheus metrics at http://ADDR/metrics (IPv4 host:port)\n"
    "  --snapshot-every  with --data-dir: store a model snapshot every N samples of a\n"
    "                session, so a restart relearns at most N (default 500; 0 never)\n"
    "  --evict-idle-seconds  with --data-dir: drop sessions unused this long from memory;\n"
    "                they are loaded again on their next call (default 1800; 0 never)\n"
    "  --frames-per-session  frames each session keeps for PostOutcome; an outcome on an\n"
    "                older one gets FAILED_PRECONDITION (default 8)\n"
    "  --max-features-per-request  feature vectors in one ClassifyFeatures, AddSamples or\n"
    "                ImportSession (default 100000; more → RESOURCE_EXHAUSTED)\n"
    "  --config FILE  settings as lines 'name value' (the flag names without --)\n"
    "  Every setting can also come from RELMAP_<NAME> in the environment (e.g.\n"
    "  RELMAP_DATA_DIR); flags override the config file, which overrides the environment.\n";

struct Options {
  std::string listen = "127.0.0.1:50051";
  int max_message_mb = 64;
  std::size_t max_sessions = 1000;
  long long max_points = 1280LL * 960LL;
  std::string port_file;
  std::string data_dir;
  std::string admin_key;
  std::string tls_cert;
  std::string tls_key;
  int max_threads = 16;
  std::size_t snapshot_every = 500;
  long long evict_idle_seconds = 1800;
  std::size_t max_features_per_request = 100000;
  std::size_t frames_per_session = 8;
  std::string metrics_listen;
  std::string metrics_port_file;
};

// The whole of a small file (a certificate or key), or ExitWithError.
std::string ReadFileOrExit(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) relmap::tools::ExitWithError("relmap-server", "cannot read " + path);
  if (text.empty()) relmap::tools::ExitWithError("relmap-server", path + " is empty or unreadable");
  return text;
}

// The flags that take a value; each can also come from a config file (a line
// "name value") or the environment (RELMAP_NAME, dashes as underscores).
constexpr std::string_view kSettings[] = {"listen",
                                          "max-message-mb",
                                          "max-sessions",
                                          "max-points",
                                          "port-file",
                                          "data-dir",
                                          "tls-cert",
                                          "tls-key",
                                          "evict-idle-seconds",
                                          "snapshot-every",
                                          "metrics-listen",
                                          "metrics-port-file",
                                          "max-threads",
                                          "admin-key-file",
                                          "max-features-per-request",
                                          "frames-per-session"};

void Apply(Options& options, std::string_view name, const std::string& value) {
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
  } else if (name == "tls-cert") {
    options.tls_cert = value;
  } else if (name == "tls-key") {
    options.tls_key = value;
  } else if (name == "evict-idle-seconds") {
    options.evict_idle_seconds = static_cast<long long>(number());
  } else if (name == "frames-per-session") {
    options.frames_per_session = static_cast<std::size_t>(number());
  } else if (name == "snapshot-every") {
    options.snapshot_every = static_cast<std::size_t>(number());
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
Options ParseArguments(int argc, char** argv) {
  using relmap::tools::ExitWithError;
  Options options;
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
                      value + ":" + std::to_string(number) + ": '" + key + "' needs a value");
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
  if (options.max_threads < 2) ExitWithError("relmap-server", "--max-threads must be at least 2");
  if (options.max_message_mb < 1 || options.max_sessions < 1 || options.max_points < 1 ||
      options.max_features_per_request < 1 || options.frames_per_session < 1) {
    ExitWithError("relmap-server", "limits must be positive");
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = ParseArguments(argc, argv);
  // Logs are diagnostics: standard error, one line per event.
  spdlog::set_default_logger(spdlog::stderr_color_mt("relmap-server"));

  // Block the stop signals before gRPC starts its threads, so that only the
  // waiting thread below receives them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  std::unique_ptr<relmap::session::SqliteSessionStore> store;
  if (!options.data_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.data_dir, error);
    auto opened = relmap::session::SqliteSessionStore::Open(options.data_dir + "/relmap.sqlite");
    if (!opened.ok()) {
      spdlog::error("cannot open the session store in {}: {}", options.data_dir,
                    opened.status().message());
      return 1;
    }
    store = std::move(opened).value();
  } else {
    spdlog::warn("no --data-dir: sessions live in memory only and are lost at exit");
  }
  relmap::session::SessionRegistry registry(options.max_sessions, store.get());
  registry.set_policy(
      {.snapshot_every = options.snapshot_every, .frame_cache = options.frames_per_session});
  if (store) {
    // Stored sessions come back into memory on their first call.
    registry.set_loader(
        [&store](const std::string& id) { return relmap::service::LoadStoredSession(*store, id); });
  }
  relmap::perception::DecodeLimits limits;
  limits.max_points = options.max_points;
  limits.max_bytes = static_cast<long long>(options.max_message_mb) << 20;
  relmap::service::RelevanceService service(
      registry, limits, options.max_features_per_request,
      options.admin_key.empty() ? std::string() : relmap::session::Sha256Hex(options.admin_key));

  grpc::EnableDefaultHealthCheckService(true);
  // Links health.proto's descriptors into the generated pool that reflection reads
  // (gRPC's own health service does not register them, grpc/grpc#36665).
  (void)grpc::health::v1::HealthCheckRequest::descriptor();
  // Without this call Debian's --as-needed link silently drops reflection.
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  int port = 0;
  std::shared_ptr<grpc::ServerCredentials> credentials = grpc::InsecureServerCredentials();
  if (!options.tls_cert.empty()) {
    grpc::SslServerCredentialsOptions tls;
    tls.pem_key_cert_pairs.push_back(
        {ReadFileOrExit(options.tls_key), ReadFileOrExit(options.tls_cert)});
    credentials = grpc::SslServerCredentials(tls);
  }
  builder.AddListeningPort(options.listen, credentials, &port);
  // A bounded pool of worker threads: when every thread is busy, gRPC answers new
  // calls with RESOURCE_EXHAUSTED instead of queueing them without bound.
  grpc::ResourceQuota quota("relmap-server");
  quota.SetMaxThreads(options.max_threads);
  builder.SetResourceQuota(quota);
  builder.SetMaxReceiveMessageSize(options.max_message_mb << 20);
  builder.SetMaxSendMessageSize(options.max_message_mb << 20);
  builder.RegisterService(&service);
  std::unique_ptr<grpc::Server> server = builder.BuildAndStart();
  if (!server || port == 0) {
    spdlog::error("cannot listen on {}", options.listen);
    return 1;
  }
  spdlog::info("relmap-server listening on {} (port {}, {}, at most {} worker threads)",
               options.listen, port, options.tls_cert.empty() ? "plaintext" : "TLS",
               options.max_threads);
  std::unique_ptr<relmap::service::MetricsHttpServer> metrics;
  if (!options.metrics_listen.empty()) {
    auto started = relmap::service::MetricsHttpServer::Start(
        options.metrics_listen, [&service] { return service.MetricsText(); });
    if (!started.ok()) {
      spdlog::error("{}", started.status().message());
      return 1;
    }
    metrics = std::move(started).value();
    spdlog::info("metrics at http://{}/metrics (port {})", options.metrics_listen, metrics->port());
    if (!options.metrics_port_file.empty()) {
      std::ofstream(options.metrics_port_file) << metrics->port() << '\n';
    }
  }
  if (!options.port_file.empty()) std::ofstream(options.port_file) << port << '\n';

  // Idle sessions leave memory (the store keeps them) so that memory follows the
  // active sessions, not every session ever created.
  std::mutex evictor_mutex;
  std::condition_variable evictor_wakeup;
  bool stopping = false;
  std::thread evictor([&] {
    if (!store || options.evict_idle_seconds <= 0) return;
    const auto period =
        std::chrono::seconds(std::clamp<long long>(options.evict_idle_seconds / 2, 1, 30));
    std::unique_lock lock(evictor_mutex);
    while (!evictor_wakeup.wait_for(lock, period, [&] { return stopping; })) {
      const auto now = std::chrono::duration_cast<std::chrono::milliseconds>(
                           std::chrono::system_clock::now().time_since_epoch())
                           .count();
      for (const std::string& id : registry.EvictIdle(now - options.evict_idle_seconds * 1000)) {
        spdlog::info("evicted session={} (idle for {} s)", id, options.evict_idle_seconds);
      }
    }
  });

  std::thread stopper([&] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    spdlog::info("signal {}: draining calls and stopping", signal);
    server->GetHealthCheckService()->SetServingStatus(false);
    server->Shutdown(std::chrono::system_clock::now() + std::chrono::seconds(10));
  });
  server->Wait();
  stopper.join();
  {
    std::lock_guard lock(evictor_mutex);
    stopping = true;
  }
  evictor_wakeup.notify_all();
  evictor.join();
  spdlog::info("relmap-server stopped");
  return 0;
}
