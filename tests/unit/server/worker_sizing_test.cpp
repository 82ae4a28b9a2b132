// The worker pool and frame queue sized from the sessions: one waiting place per session
// and two spare, never fewer than 8, never more than the memory bound; threads for the
// waiting, the running and the cheap calls; an operator's fixed values kept as given.
#include "worker_sizing.h"

#include <gtest/gtest.h>

namespace relmap::server {
namespace {

TEST(WorkerSizing, AWaitingPlaceAndAThreadForEverySession) {
  const WorkerSizingPolicy policy{.concurrent_frames = 2, .max_queued_frames = 96};
  // 64 sessions: 66 places; 2 running + 66 waiting + 8 for cheap calls.
  const WorkerPool pool = SizeWorkerPool(policy, 64);
  EXPECT_EQ(pool.queued_frames, 66u);
  EXPECT_EQ(pool.threads, 76);
  // A handful of sessions keeps the old pool's 8 places: 2 + 8 + 8 threads.
  EXPECT_EQ(SizeWorkerPool(policy, 0).queued_frames, 8u);
  EXPECT_EQ(SizeWorkerPool(policy, 0).threads, 18);
  EXPECT_EQ(SizeWorkerPool(policy, 7).queued_frames, 9u);
}

TEST(WorkerSizing, TheMemoryBoundCapsTheQueue) {
  const WorkerSizingPolicy policy{.concurrent_frames = 4, .max_queued_frames = 20};
  EXPECT_EQ(SizeWorkerPool(policy, 500).queued_frames, 20u);
  EXPECT_EQ(SizeWorkerPool(policy, 500).threads, 4 + 20 + 8);
}

TEST(WorkerSizing, FixedValuesAreKept) {
  WorkerSizingPolicy policy{.concurrent_frames = 2, .max_queued_frames = 96};
  policy.fixed_threads = 16;
  policy.fixed_queued_frames = 8;
  const WorkerPool pool = SizeWorkerPool(policy, 64);
  EXPECT_EQ(pool.queued_frames, 8u);
  EXPECT_EQ(pool.threads, 16);
}

TEST(WorkerSizing, AQuarterOfTheMemoryAtTheLargestRequest) {
  // 24 GiB / 4 = 6 GiB, at 64 MiB a request: 96 waiting calls.
  EXPECT_EQ(QueuedFramesMemoryBound(std::uint64_t{24} << 30, 64), 96u);
  // A small machine still queues the old pool's 8.
  EXPECT_EQ(QueuedFramesMemoryBound(std::uint64_t{1} << 30, 64), kMinQueuedFrames);
  EXPECT_EQ(QueuedFramesMemoryBound(0, 64), kMinQueuedFrames);
  EXPECT_GT(PhysicalMemoryBytes(), 0u);
}

}  // namespace
}  // namespace relmap::server
