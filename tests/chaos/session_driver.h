// One robot of a chaos run: a thread that creates its session once, then loops
// ComputeMaps → PostOutcome of the target → AddSamples of a small batch, each write
// with its own request id and repeated with that id until the server answers, and
// records in a Ledger what the server acknowledged or refused.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include "chaos/chaos_ledger.h"
#include "chaos/labelled_stream.h"
#include "common/status.h"
#include "relevance_client.h"

namespace relmap::chaos {

struct DriverSettings {
  std::string address;        // the server, or the load balancer in front of servers
  int index = 0;              // the session's number in the run, for request ids and logs
  std::uint64_t seed = 1;     // the session's config seed and its samples' stream
  int samples_per_batch = 4;  // per AddSamples
  // A write without an answer this long (the server down, the session nowhere) ends
  // the driver with a failure.
  std::chrono::seconds give_up{120};
};

class SessionDriver {
 public:
  // `cloud` is uploaded by every ComputeMaps; it must outlive the driver.
  SessionDriver(DriverSettings settings, const v1::Cloud& cloud);
  ~SessionDriver();
  SessionDriver(const SessionDriver&) = delete;
  SessionDriver& operator=(const SessionDriver&) = delete;

  // CreateSession (repeated while the server does not answer), then the loop on a
  // thread of its own.
  Status Start();
  // Ends the loop once the write in progress has its answer; waits for it.
  void Stop();

  // Writes acknowledged so far (outcomes and AddSamples calls): the run's progress.
  std::uint64_t acknowledged_writes() const { return acknowledged_writes_.load(); }
  // Samples acknowledged so far (an outcome is one, a batch its size).
  std::uint64_t acknowledged_samples() const { return acknowledged_samples_.load(); }
  // Whether a write is on the wire now (for "killed mid-write").
  bool writing() const { return writing_.load(); }
  // Whether the loop still runs: false once it stopped on a failure (or Stop).
  bool running() const { return running_.load(); }

  // After Stop: what the server answered, how the loop ended, the calls repeated by
  // status code.
  const Ledger& ledger() const { return ledger_; }
  const Status& failure() const { return failure_; }
  std::map<std::string, std::uint64_t> repeats() const;
  const client::SessionHandle& session() const { return session_; }
  client::RelevanceClient& client() { return client_; }

 private:
  enum class Answer { kAcknowledged, kRefused, kNone };

  void Loop();
  // One push: maps of the cloud, the target's outcome, a batch of samples. False when
  // the driver must stop (failure_ set).
  bool Push(std::uint64_t push);
  // `call` until it returns a status that is the server's answer; kNone (and
  // failure_) after give_up without one, or on a status that is no answer.
  Answer Repeat(const char* what, const std::function<grpc::Status()>& call,
                const std::function<bool(const grpc::Status&)>& refused);
  void CountRepeat(const grpc::Status& status);

  const DriverSettings settings_;
  const v1::Cloud& cloud_;
  client::RelevanceClient client_;
  client::SessionHandle session_;
  LabelledStream stream_;
  Ledger ledger_;
  Status failure_;
  std::atomic<std::uint64_t> acknowledged_writes_{0};
  std::atomic<std::uint64_t> acknowledged_samples_{0};
  std::atomic<bool> writing_{false};
  std::atomic<bool> running_{false};
  std::atomic<bool> stop_{false};
  mutable std::mutex repeats_mutex_;
  std::map<std::string, std::uint64_t> repeats_;
  std::thread thread_;
};

}  // namespace relmap::chaos
