// Options become the layers' settings here, and nowhere else in relmap-server.
#include "service_setup.h"

#include <spdlog/spdlog.h>

#include <chrono>

#include "service/config_mapping.h"
#include "session/credentials.h"
#include "store_opening.h"

namespace relmap::server {

StatusOr<std::unique_ptr<session::SessionStore>> OpenConfiguredStore(const ServerOptions& options) {
  if (options.store.empty()) {
    spdlog::warn("no --store or --data-dir: sessions live in memory only and are lost at exit");
    return std::unique_ptr<session::SessionStore>();
  }
  auto opened = OpenSessionStore(options.store, std::chrono::seconds(options.lease_seconds));
  if (!opened.ok()) {
    return Status(opened.status().code(), "cannot open the session store " +
                                              StoreForLogs(options.store) + ": " +
                                              opened.status().message());
  }
  spdlog::info("session store {}", StoreForLogs(options.store));
  return opened;
}

std::unique_ptr<session::SessionRegistry> BuildRegistry(const ServerOptions& options,
                                                        session::SessionStore* store) {
  // The stored settings are the API's SessionConfig, which the service reads.
  auto registry = std::make_unique<session::SessionRegistry>(options.max_sessions, store,
                                                             service::SettingsOfStoredSession);
  registry->set_policy(
      {.snapshot_every = options.snapshot_every,
       .snapshot_after_learning = std::chrono::milliseconds(options.snapshot_after_learning_ms),
       .frame_cache = options.frames_per_session});
  return registry;
}

service::ServiceLimits ServiceLimitsOf(const ServerOptions& options, const WorkerPool& pool) {
  service::ServiceLimits limits;
  limits.decode.max_points = options.max_points;
  limits.decode.max_bytes = static_cast<long long>(options.max_message_mb) << 20;
  limits.max_features_per_request = options.max_features_per_request;
  limits.concurrent_frames = options.max_concurrent_frames;
  limits.queued_frames = pool.queued_frames;
  limits.max_frame_wait = std::chrono::milliseconds(options.max_frame_wait_ms);
  return limits;
}

WorkerSizingPolicy WorkerSizingOf(const ServerOptions& options) {
  WorkerSizingPolicy policy;
  policy.concurrent_frames = options.max_concurrent_frames;
  policy.max_queued_frames = QueuedFramesMemoryBound(PhysicalMemoryBytes(), options.max_message_mb);
  if (options.max_threads != 0) policy.fixed_threads = options.max_threads;
  if (options.max_queued_frames != 0) policy.fixed_queued_frames = options.max_queued_frames;
  return policy;
}

std::string AdminKeyHashOf(const ServerOptions& options) {
  return options.admin_key.empty() ? std::string() : session::Sha256Hex(options.admin_key);
}

}  // namespace relmap::server
