// The push loop of every session at once, on the async gRPC API: each session runs
// ComputeMaps → PostOutcome on the returned target, cycle after cycle, with one call
// in flight per session. All calls share one completion queue, served by the
// calling thread; nothing blocks per session.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "client_options.h"
#include "latency_samples.h"
#include "load_cloud.h"
#include "relevance_client.h"
#include "relmap/v1/relevance_service.grpc.pb.h"

namespace relmap::load {

// A session as the load loop drives it.
struct LoadSession {
  client::SessionHandle handle;
  // The seed the session was created with; also seeds its label coins and the
  // jitter of its backoffs.
  std::uint64_t seed = 0;
};

struct LoadPlan {
  // Push cycles per session; 0: until `seconds` have passed.
  std::uint64_t cycles = 20;
  // Wall-clock limit: no session starts a cycle after it; 0: none.
  double seconds = 0;
  // Of one call, its retries and their backoffs included; past it the session fails.
  std::chrono::milliseconds deadline{120000};
  // Calls answered RESOURCE_EXHAUSTED because the server's worker pool was full
  // are retried after a backoff of initial · 2^(attempt−2), capped, ±50% jitter,
  // while the deadline allows, and at most max_attempts times in all.
  client::RetryPolicy retry{.max_attempts = std::numeric_limits<int>::max(),
                            .initial_backoff = std::chrono::milliseconds(20),
                            .max_backoff = std::chrono::milliseconds(1000)};
};

// Means of ComputeMaps' stage timings as the server measured them.
struct ServerStageMeans {
  double admission_ms = 0, decode_ms = 0, filter_ms = 0, supervoxels_ms = 0, features_ms = 0,
         maps_ms = 0;
};

struct LoadResults {
  double elapsed_seconds = 0;  // first call sent → last answer received
  std::uint64_t cycles = 0;    // completed: ComputeMaps and PostOutcome both answered
  // Client-observed, from the first attempt's start to the answer, so retries and
  // their backoffs are included.
  LatencySamples compute_maps_ms;
  LatencySamples post_outcome_ms;
  LatencySamples cycle_ms;
  // ComputeMaps' timings.total_ms: the handler's own time, without transport,
  // (de)serialisation or waiting for a worker thread.
  LatencySamples server_compute_maps_ms;
  ServerStageMeans server_stages;
  double mean_supervoxels = 0;
  // Attempts answered RESOURCE_EXHAUSTED (worker pool full) and retried.
  std::uint64_t compute_maps_exhausted = 0;
  std::uint64_t post_outcome_exhausted = 0;
  std::uint64_t moveable_labels = 0;
  std::uint64_t not_moveable_labels = 0;
  // Sessions that stopped on an error, and the first error.
  std::uint64_t failed_sessions = 0;
  std::string first_failure;
};

struct LoadProgress {
  double elapsed_seconds = 0;
  double fraction_done = 0;  // of the planned cycles, or of the planned time
  std::uint64_t cycles = 0;
  std::uint64_t calls = 0;
  std::uint64_t exhausted = 0;
};

// Runs the loop of every session until each has done `plan.cycles` or the time is
// up. `progress` is called about once per second and once at the end.
LoadResults RunLoad(v1::RelevanceService::Stub& stub, const std::vector<LoadSession>& sessions,
                    const LoadCloud& cloud, const LoadPlan& plan,
                    const std::function<void(const LoadProgress&)>& progress);

}  // namespace relmap::load
