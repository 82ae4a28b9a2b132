// The stores' durability and concurrency promises: every acknowledged append
// survives kill -9 of the server, and appends from several threads all land.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <csignal>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "session/store_contract.h"

namespace relmap::session {
namespace {

using testing::MakeRecord;
using testing::Numbered;
using testing::SessionStoreDurability;

// Distinct, non-trivial features for sample i of session `s`.
std::vector<double> Features(int s, int i) { return {s + i / 7.0, -i * 1e-310, 1.0 / (i + 3)}; }

TEST_P(SessionStoreDurability, EveryAcknowledgedAppendSurvivesKillNine) {
  {
    auto store = OpenStore();
    ASSERT_TRUE(store->CreateSession(MakeRecord("s")).ok());
  }  // closed: the child opens its own connection, never one shared across fork
  int ack[2];
  ASSERT_EQ(pipe(ack), 0);
  constexpr int kAppends = 30;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(ack[0]);
    // Another server process, which takes the session before writing to it.
    auto store = backend_->Open();
    if (!store.ok() || !(*store)->AcquireOwnership("s").ok()) _exit(2);
    for (int i = 0; i < kAppends; ++i) {
      const auto x = Features(0, i);
      auto sequence = (*store)->AppendSample("s", Numbered("r", i), x, i % 2);
      if (!sequence.ok()) _exit(3);
      // The acknowledgement a client would get; then, for the last one, no chance
      // to close, checkpoint or flush anything.
      const std::int64_t acknowledged = *sequence;
      if (write(ack[1], &acknowledged, sizeof acknowledged) != sizeof acknowledged) _exit(4);
      if (i == kAppends - 1) raise(SIGKILL);
    }
    _exit(5);
  }
  close(ack[1]);
  std::vector<std::int64_t> acknowledged;
  std::int64_t sequence = 0;
  while (read(ack[0], &sequence, sizeof sequence) == sizeof sequence) {
    acknowledged.push_back(sequence);
  }
  close(ack[0]);
  int wait_status = 0;
  ASSERT_EQ(waitpid(child, &wait_status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(wait_status)) << "child exited with " << WEXITSTATUS(wait_status);
  EXPECT_EQ(WTERMSIG(wait_status), SIGKILL);
  ASSERT_EQ(acknowledged.size(), static_cast<std::size_t>(kAppends));

  auto store = OpenStore();
  auto samples = store->LoadSamples("s");
  ASSERT_TRUE(samples.ok()) << samples.status().message();
  ASSERT_EQ(samples->size(), acknowledged.size());
  for (std::size_t i = 0; i < acknowledged.size(); ++i) {
    const StoredSample& sample = (*samples)[i];
    EXPECT_EQ(sample.sequence, acknowledged[i]);
    EXPECT_EQ(sample.request_id, Numbered("r", static_cast<int>(i)));
    EXPECT_EQ(sample.label, static_cast<int>(i % 2));
    EXPECT_EQ(sample.features, Features(0, static_cast<int>(i)));
  }
}

TEST_P(SessionStoreDurability, ConcurrentAppendsToDifferentSessionsAllLand) {
  auto store = OpenStore();
  constexpr int kThreads = 4;
  constexpr int kAppends = 25;
  for (int s = 0; s < kThreads; ++s) {
    ASSERT_TRUE(store->CreateSession(MakeRecord(Numbered("s", s))).ok());
  }
  std::vector<std::vector<std::int64_t>> sequences(kThreads);
  std::vector<std::thread> threads;
  for (int s = 0; s < kThreads; ++s) {
    threads.emplace_back([&, s] {
      for (int i = 0; i < kAppends; ++i) {
        auto sequence =
            store->AppendSample(Numbered("s", s), Numbered("r", i), Features(s, i), i % 2);
        sequences[s].push_back(sequence.ok() ? *sequence : -1);
      }
    });
  }
  for (std::thread& thread : threads) thread.join();

  for (int s = 0; s < kThreads; ++s) {
    auto samples = store->LoadSamples(Numbered("s", s));
    ASSERT_TRUE(samples.ok()) << samples.status().message();
    ASSERT_EQ(samples->size(), static_cast<std::size_t>(kAppends));
    for (int i = 0; i < kAppends; ++i) {
      EXPECT_EQ(sequences[s][i], i);
      EXPECT_EQ((*samples)[i].features, Features(s, i));
    }
  }
}

}  // namespace
}  // namespace relmap::session
