// relmap-server: the relevance server. Configuration by flags; gRPC health and
// reflection on; SIGTERM or SIGINT stop it gracefully (in-flight calls finish).
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <fstream>
#include <thread>

#include "drain_on_signal.h"
#include "grpc_serving.h"
#include "idle_eviction.h"
#include "metrics_endpoint.h"
#include "server_options.h"
#include "service/relevance_service.h"
#include "service_setup.h"
#include "session/registry/memory_release.h"
#include "stop_signals.h"

namespace {

// One arena per core: the frames that allocate most run at most --max-concurrent-frames at
// once (2 by default). Blocks of 32 MiB and more (a cloud near --max-points) are mapped on
// their own and unmapped when freed; smaller ones (a Kinect frame's request and its 9.8 MB
// decoded cloud) come from the arenas and are reused frame after frame. With a 256 KiB
// threshold every frame mapped ~12,000 fresh pages and the server spent a fifth of its CPU
// in the kernel; 32 MiB maps 8-13 % more frames per second for 45-130 MB more RSS under
// load and none once the sessions go (docs/reliability.md, "Memory"). Fixed, the threshold
// does not raise glibc's trim threshold, so free memory at an arena's top is still returned.
constexpr std::size_t kMmapThresholdBytes = std::size_t{32} << 20;

}  // namespace

int main(int argc, char** argv) {
  using namespace relmap::server;
  const ServerOptions options = ParseServerOptions(argc, argv);
  relmap::session::ConfigureAllocator(
      std::max(2, static_cast<int>(std::thread::hardware_concurrency())), kMmapThresholdBytes);
  // Logs are diagnostics: standard error, one line per event.
  spdlog::set_default_logger(spdlog::stderr_color_mt("relmap-server"));
  StopSignals stop_signals = StopSignals::Block();  // before gRPC starts its threads

  auto store = OpenConfiguredStore(options);
  if (!store.ok()) {
    spdlog::error("{}", store.status().message());
    return 1;
  }
  const auto registry = BuildRegistry(options, store->get());
  const WorkerSizingPolicy sizing = WorkerSizingOf(options);
  const WorkerPool pool = SizeWorkerPool(sizing, 0);
  relmap::service::RelevanceService service(*registry, ServiceLimitsOf(options, pool),
                                            AdminKeyHashOf(options));

  auto serving = StartServing(options, pool.threads, service);
  if (!serving.ok()) {
    spdlog::error("{}", serving.status().message());
    return 1;
  }
  const bool sized = !sizing.fixed_threads || !sizing.fixed_queued_frames;
  spdlog::info(
      "relmap-server listening on {} (port {}, {}, {} worker threads and {} waiting frames{})",
      options.listen, serving->port, options.tls_cert.empty() ? "plaintext" : "TLS", pool.threads,
      pool.queued_frames,
      sized ? fmt::format(", growing with the sessions up to {} waiting",
                          SizeWorkerPool(sizing, sizing.max_queued_frames).queued_frames)
            : std::string());
  // Under the registry's lock, so that the sizes arrive in order.
  registry->set_size_observer([&sizing, &service, quota = serving->quota.get()](std::size_t n) {
    const WorkerPool resized = SizeWorkerPool(sizing, n);
    service.SetQueuedFrames(resized.queued_frames);
    quota->SetMaxThreads(resized.threads);
  });
  auto metrics = StartMetricsEndpoint(options, service);
  if (!metrics.ok()) {
    spdlog::error("{}", metrics.status().message());
    return 1;
  }
  if (!options.port_file.empty()) std::ofstream(options.port_file) << serving->port << '\n';

  {
    const IdleEviction eviction(*registry, options.evict_idle_seconds,
                                options.session_idle_expiry_seconds);
    {
      const DrainOnSignal drain(stop_signals, *serving->server, options.drain_seconds);
      serving->server->Wait();
    }
    // No call runs any more: hand the sessions over, so another server sharing the
    // store takes them at once instead of after their leases.
    registry->ReleaseAll();
    registry->set_size_observer({});
  }
  spdlog::info("relmap-server stopped");
  return 0;
}
