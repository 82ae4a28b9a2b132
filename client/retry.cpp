// Retry classification and exponential backoff with jitter.
#include "retry.h"

#include <algorithm>

#include "error_reason.h"

namespace relmap::client {

bool IsRetryable(const grpc::Status& status, Idempotence idempotence, bool pushback) {
  // relmap-server says so: it did nothing, and will do it later or elsewhere.
  const v1::ErrorReason reason = ReasonOf(status);
  if (reason == v1::BUSY || reason == v1::SESSION_OWNED_ELSEWHERE) return true;
  // A pushback trailer says the same (gRPC's retry design A6) on the codes that mean
  // "not now", also from a server that sends no reasons.
  const grpc::StatusCode code = status.error_code();
  const bool not_now =
      code == grpc::StatusCode::RESOURCE_EXHAUSTED || code == grpc::StatusCode::UNAVAILABLE;
  if (pushback && not_now) return true;
  // gRPC's own text for a sync server whose ResourceQuota has no thread left
  // (src/cpp/server/server_cc.cc): no handler ran, so no reason could be given.
  // relmap's own RESOURCE_EXHAUSTED answers (oversized clouds, too many sessions)
  // carry other messages and are final.
  constexpr char kThreadpoolExhausted[] = "Server Threadpool Exhausted";
  if (code == grpc::StatusCode::RESOURCE_EXHAUSTED &&
      status.error_message() == kThreadpoolExhausted) {
    return true;
  }
  // A broken connection: the call may or may not have run.
  return code == grpc::StatusCode::UNAVAILABLE && idempotence == Idempotence::kIdempotent;
}

std::optional<std::chrono::milliseconds> PushbackOf(const grpc::ClientContext& context) {
  const auto& trailers = context.GetServerTrailingMetadata();
  const auto it = trailers.find("grpc-retry-pushback-ms");
  if (it == trailers.end()) return std::nullopt;
  long long milliseconds = 0;
  for (const char c : it->second) {
    if (c < '0' || c > '9' || milliseconds > 3'600'000) return std::nullopt;  // not a pushback
    milliseconds = milliseconds * 10 + (c - '0');
  }
  return std::chrono::milliseconds(milliseconds);
}

std::chrono::milliseconds BackoffBefore(int attempt, const RetryPolicy& policy,
                                        double unit_random) {
  const int doublings = std::clamp(attempt - 2, 0, 30);
  const double base = std::min(
      static_cast<double>(policy.initial_backoff.count()) * static_cast<double>(1ull << doublings),
      static_cast<double>(policy.max_backoff.count()));
  return std::chrono::milliseconds(static_cast<long long>(base * (0.5 + unit_random)));
}

}  // namespace relmap::client
