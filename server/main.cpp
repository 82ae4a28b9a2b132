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
#include "server_options.h"
#include "service/config_mapping.h"
#include "service/metrics_http.h"
#include "service/relevance_service.h"
#include "session/credentials.h"
#include "session/session_registry.h"
#include "store_opening.h"
#include "tools/command_line.h"

namespace {

// The whole of a small file (a certificate or key), or ExitWithError.
std::string ReadFileOrExit(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) relmap::tools::ExitWithError("relmap-server", "cannot read " + path);
  if (text.empty()) relmap::tools::ExitWithError("relmap-server", path + " is empty or unreadable");
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  const relmap::server::ServerOptions options = relmap::server::ParseServerOptions(argc, argv);
  // Logs are diagnostics: standard error, one line per event.
  spdlog::set_default_logger(spdlog::stderr_color_mt("relmap-server"));

  // Block the stop signals before gRPC starts its threads, so that only the
  // waiting thread below receives them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  std::unique_ptr<relmap::session::SessionStore> store;
  if (!options.store.empty()) {
    auto opened = relmap::server::OpenSessionStore(options.store,
                                                   std::chrono::seconds(options.lease_seconds));
    if (!opened.ok()) {
      spdlog::error("cannot open the session store {}: {}",
                    relmap::server::StoreForLogs(options.store), opened.status().message());
      return 1;
    }
    store = std::move(opened).value();
    spdlog::info("session store {}", relmap::server::StoreForLogs(options.store));
  } else {
    spdlog::warn("no --store or --data-dir: sessions live in memory only and are lost at exit");
  }
  // Stored sessions come back into memory on their first call; their stored settings
  // are the API's SessionConfig, which the service reads.
  relmap::session::SessionRegistry registry(options.max_sessions, store.get(),
                                            relmap::service::SettingsOfStoredSession);
  registry.set_policy(
      {.snapshot_every = options.snapshot_every, .frame_cache = options.frames_per_session});
  relmap::service::ServiceLimits limits;
  limits.decode.max_points = options.max_points;
  limits.decode.max_bytes = static_cast<long long>(options.max_message_mb) << 20;
  limits.max_features_per_request = options.max_features_per_request;
  limits.concurrent_frames = options.max_concurrent_frames;
  limits.queued_frames = options.max_queued_frames;
  relmap::service::RelevanceService service(
      registry, limits,
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
  // Probes may ask for the whole server ("") or for the service by name.
  server->GetHealthCheckService()->SetServingStatus(
      relmap::v1::RelevanceService::service_full_name(), true);
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
    // NOT_SERVING first, while calls are still served, so that load balancers and
    // Kubernetes move traffic away before the server refuses it.
    server->GetHealthCheckService()->SetServingStatus(false);
    spdlog::info("signal {}: NOT_SERVING, draining for {} s, then stopping", signal,
                 options.drain_seconds);
    std::this_thread::sleep_for(std::chrono::seconds(options.drain_seconds));
    server->Shutdown(std::chrono::system_clock::now() + std::chrono::seconds(10));
  });
  server->Wait();
  stopper.join();
  // No call runs any more: hand the sessions over, so another server sharing the
  // store takes them at once instead of after their leases.
  registry.ReleaseAll();
  {
    std::lock_guard lock(evictor_mutex);
    stopping = true;
  }
  evictor_wakeup.notify_all();
  evictor.join();
  spdlog::info("relmap-server stopped");
  return 0;
}
