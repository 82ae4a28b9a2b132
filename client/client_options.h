// How a RelevanceClient connects and how patient it is: message size, per-call
// deadline, retries of the calls that can safely be repeated, TLS.
#pragma once

#include <chrono>
#include <string>

namespace relmap::client {

struct RetryPolicy {
  // Attempts per call, the first one included (1 = never retry). A busy server's
  // answers with a pushback (it did nothing and says when to come back) do not
  // count: those are repeated until the deadline.
  int max_attempts = 5;
  // Backoff before the second attempt; doubled each time up to `max_backoff`,
  // with ±50% jitter so that many robots do not retry in lockstep.
  std::chrono::milliseconds initial_backoff{50};
  std::chrono::milliseconds max_backoff{2000};
};

struct ClientOptions {
  // host:port of the server.
  std::string address = "127.0.0.1:50051";
  // Largest message in either direction (clouds are a few MB).
  int max_message_bytes = 64 << 20;
  // The whole call, retries and backoffs included. A 640×480 ComputeMaps takes
  // ~0.15 s on the server; the default leaves room for a loaded one.
  std::chrono::milliseconds deadline{30000};
  RetryPolicy retry;
  // PEM of the CA that signed the server's certificate: TLS when set, plaintext
  // when empty.
  std::string tls_root_certificates;
};

}  // namespace relmap::client
