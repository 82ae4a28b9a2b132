// When a failed call may be sent again, and how long to wait before doing so.
#pragma once

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <optional>

#include "client_options.h"

namespace relmap::client {

// Whether repeating a call that the server may already have carried out is harmless:
// reads, and writes that carry a request id the server deduplicates on.
enum class Idempotence { kIdempotent, kNotIdempotent };

// A call may be retried when the server provably did not run it: relmap-server's
// reason says so (BUSY: its frame admission turned the call away;
// SESSION_OWNED_ELSEWHERE: another server owns the session in a shared store, for
// now; error_reason.h), or its worker pool was full (gRPC answers RESOURCE_EXHAUSTED
// "Server Threadpool Exhausted" before any handler runs, so that text, gRPC's, carries
// no reason), or it answered RESOURCE_EXHAUSTED or UNAVAILABLE with a
// grpc-retry-pushback-ms trailer (`pushback`). For idempotent calls only, also when the
// connection failed (UNAVAILABLE) and the call may or may not have run. Every other
// status is the server's answer and is returned as it is.
bool IsRetryable(const grpc::Status& status, Idempotence idempotence, bool pushback = false);

// The server's grpc-retry-pushback-ms trailer, if `context`'s call ended with one.
std::optional<std::chrono::milliseconds> PushbackOf(const grpc::ClientContext& context);

// The wait before attempt `attempt` (2, 3, ...): initial_backoff · 2^(attempt−2),
// capped at max_backoff, times the jitter factor 0.5 + `unit_random` (a draw in [0, 1)).
std::chrono::milliseconds BackoffBefore(int attempt, const RetryPolicy& policy, double unit_random);

}  // namespace relmap::client
