// How many calls the server lets wait for a frame slot, and how many worker threads it
// keeps, from the sessions in memory. Each robot has about one frame call in flight, so
// one waiting place per session (and a little slack) means no robot is refused while
// all are served in turn (session/frame_admission.h); the threads are those places, the
// running frames and the cheap calls. A fixed pool sized for a few robots refused most
// of 64 and, refused and backing off, some waited many turns: ComputeMaps p99 13 × p50
// (docs/reliability.md, "Fairness under load").
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace relmap::server {

struct WorkerSizingPolicy {
  std::size_t concurrent_frames = 2;
  // The memory bound on the waiting calls (QueuedFramesMemoryBound).
  std::size_t max_queued_frames = 64;
  // --max-threads and --max-queued-frames, when the operator fixed them.
  std::optional<int> fixed_threads;
  std::optional<std::size_t> fixed_queued_frames;
};

struct WorkerPool {
  std::size_t queued_frames = 0;
  int threads = 0;
};

// Never fewer than the old fixed pool (8 waiting), so a lone session's bursts still wait.
inline constexpr std::size_t kMinQueuedFrames = 8;
// Places beyond one per session: sessions being created, a robot with a second frame.
inline constexpr std::size_t kSpareQueuedFrames = 2;
// Threads for the calls that never wait for a frame slot (outcomes, classification,
// health, listings), so that they are not refused while frames wait.
inline constexpr int kCheapCallThreads = 8;

// The pool for `sessions` in memory.
WorkerPool SizeWorkerPool(const WorkerSizingPolicy& policy, std::size_t sessions);

// Waiting calls that a quarter of `physical_memory_bytes` holds when each holds a request
// of the largest size the server takes (`max_message_mb`); at least kMinQueuedFrames.
std::size_t QueuedFramesMemoryBound(std::uint64_t physical_memory_bytes,
                                    std::size_t max_message_mb);

// This machine's physical memory (sysconf), or 0 when it cannot be read.
std::uint64_t PhysicalMemoryBytes();

}  // namespace relmap::server
