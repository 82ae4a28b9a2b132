// Sizing the worker pool and the frame queue from the sessions in memory.
#include "worker_sizing.h"

#include <unistd.h>

#include <algorithm>

namespace relmap::server {

WorkerPool SizeWorkerPool(const WorkerSizingPolicy& policy, std::size_t sessions) {
  WorkerPool pool;
  pool.queued_frames = policy.fixed_queued_frames.value_or(
      std::clamp(sessions + kSpareQueuedFrames, kMinQueuedFrames,
                 std::max(kMinQueuedFrames, policy.max_queued_frames)));
  if (policy.fixed_threads) {
    pool.threads = *policy.fixed_threads;
  } else {
    pool.threads =
        static_cast<int>(policy.concurrent_frames + pool.queued_frames) + kCheapCallThreads;
  }
  return pool;
}

std::size_t QueuedFramesMemoryBound(std::uint64_t physical_memory_bytes,
                                    std::size_t max_message_mb) {
  const std::uint64_t request_bytes = static_cast<std::uint64_t>(max_message_mb) << 20;
  if (request_bytes == 0) return kMinQueuedFrames;
  return std::max<std::size_t>(kMinQueuedFrames, physical_memory_bytes / 4 / request_bytes);
}

std::uint64_t PhysicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
}

}  // namespace relmap::server
