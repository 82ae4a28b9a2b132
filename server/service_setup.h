// What relmap-server builds from its options before it serves: the store, the
// registry over it, the service's limits and admin key, and the worker pool's sizing.
#pragma once

#include <memory>
#include <string>

#include "common/status.h"
#include "server_options.h"
#include "service/relevance_service.h"
#include "session/registry/session_registry.h"
#include "session/store/session_store.h"
#include "worker_sizing.h"

namespace relmap::server {

// The store of --store or --data-dir, or null (with a warning: sessions live in
// memory only) without either; the store's error when it cannot be opened.
StatusOr<std::unique_ptr<session::SessionStore>> OpenConfiguredStore(const ServerOptions& options);

// The registry of the options' limits and policy over `store` (may be null), which
// brings stored sessions back on their first call.
std::unique_ptr<session::SessionRegistry> BuildRegistry(const ServerOptions& options,
                                                        session::SessionStore* store);

// The limits of the options; the frame queue's bound is `pool`'s, which the sessions move.
service::ServiceLimits ServiceLimitsOf(const ServerOptions& options, const WorkerPool& pool);

// The worker pool's sizing: fixed where --max-threads or --max-queued-frames say so, else
// from the sessions, bounded by this machine's memory.
WorkerSizingPolicy WorkerSizingOf(const ServerOptions& options);

// SHA-256 hex of --admin-key, or empty without one.
std::string AdminKeyHashOf(const ServerOptions& options);

}  // namespace relmap::server
