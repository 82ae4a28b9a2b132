// FrameAdmission: at most `concurrent` calls run, at most `queued` wait, the rest are
// refused at once, and a waiter gives up at its deadline.
#include "session/intake/frame_admission.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace relmap::session {
namespace {

using std::chrono::milliseconds;
using std::chrono::system_clock;

TEST(FrameAdmission, RefusesAtOnceWhenEverySlotRunsAndNoneMayWait) {
  FrameAdmission admission(1, 0);
  auto first = admission.Enter(system_clock::now() + milliseconds(1000));
  ASSERT_TRUE(first.has_value());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(admission.Enter(system_clock::now() + milliseconds(1000)).has_value());
  EXPECT_LT(std::chrono::steady_clock::now() - start, milliseconds(100));
}

TEST(FrameAdmission, AWaiterTakesTheSlotThatIsFreed) {
  FrameAdmission admission(1, 1);
  std::optional<FrameAdmission::Ticket> first =
      admission.Enter(system_clock::now() + milliseconds(1000));
  std::atomic<bool> admitted = false;
  std::thread waiter(
      [&] { admitted = admission.Enter(system_clock::now() + milliseconds(5000)).has_value(); });
  while (admission.waiting() == 0) std::this_thread::yield();
  first.reset();  // the ticket's release wakes the waiter
  waiter.join();
  EXPECT_TRUE(admitted);
  EXPECT_EQ(admission.running(), 0u);
}

TEST(FrameAdmission, TheQueueIsBoundedAndAWaiterGivesUpAtItsDeadline) {
  FrameAdmission admission(1, 1);
  auto running = admission.Enter(system_clock::now());
  ASSERT_TRUE(running.has_value());
  std::atomic<bool> admitted = true;
  std::thread waiter(
      [&] { admitted = admission.Enter(system_clock::now() + milliseconds(200)).has_value(); });
  while (admission.waiting() == 0) std::this_thread::yield();
  EXPECT_FALSE(admission.Enter(system_clock::now() + milliseconds(1000)).has_value());  // full
  waiter.join();
  EXPECT_FALSE(admitted);  // the slot stayed taken past the waiter's deadline
  EXPECT_EQ(admission.waiting(), 0u);
}

TEST(FrameAdmission, TheQueueBoundFollowsTheServersSessions) {
  FrameAdmission admission(1, 0);
  auto running = admission.Enter(system_clock::now());
  ASSERT_TRUE(running.has_value());
  EXPECT_FALSE(admission.Enter(system_clock::now() + milliseconds(1000)).has_value());
  admission.set_queue_bound(1);
  EXPECT_EQ(admission.queue_bound(), 1u);
  std::atomic<bool> admitted = false;
  std::thread waiter(
      [&] { admitted = admission.Enter(system_clock::now() + milliseconds(5000)).has_value(); });
  while (admission.waiting() == 0) std::this_thread::yield();
  admission.set_queue_bound(0);  // the waiter keeps its place
  running.reset();
  waiter.join();
  EXPECT_TRUE(admitted);
}

TEST(FrameAdmission, ServesTheWaitingSessionsInTurnHoweverManyCallsOneSends) {
  FrameAdmission admission(1, 10);
  std::optional<FrameAdmission::Ticket> running =
      admission.Enter(system_clock::now() + milliseconds(1000), "x");
  std::mutex mutex;
  std::vector<std::string> order;
  std::vector<std::thread> waiters;
  // Session a queues three calls, then b one: b's call goes second, not last.
  for (const char* call : {"a1", "a2", "a3", "b1"}) {
    const std::size_t before = admission.waiting();
    waiters.emplace_back([&, call] {
      const std::string session(call, 1);
      auto ticket = admission.Enter(system_clock::now() + milliseconds(10000), session);
      const std::lock_guard lock(mutex);
      order.emplace_back(ticket ? call : "refused");
    });  // the ticket goes when the call has recorded itself: the next is admitted
    while (admission.waiting() == before) std::this_thread::yield();
  }
  running.reset();
  for (std::thread& waiter : waiters) waiter.join();
  EXPECT_EQ(order, (std::vector<std::string>{"a1", "b1", "a2", "a3"}));
  EXPECT_EQ(admission.running(), 0u);
  EXPECT_EQ(admission.waiting(), 0u);
}

TEST(FrameAdmission, AFreedSlotGoesToAWaiterNotToACallArrivingMeanwhile) {
  FrameAdmission admission(1, 1);
  std::optional<FrameAdmission::Ticket> running =
      admission.Enter(system_clock::now() + milliseconds(1000), "a");
  std::atomic<bool> waited = false;
  std::atomic<bool> release = false;
  std::thread waiter([&] {
    const auto ticket = admission.Enter(system_clock::now() + milliseconds(10000), "b");
    waited = ticket.has_value();
    while (!release) std::this_thread::yield();  // b holds its slot until told
  });
  while (admission.waiting() == 0) std::this_thread::yield();
  running.reset();  // handed to b at once: the slot is never free
  EXPECT_EQ(admission.running(), 1u);
  EXPECT_FALSE(admission.Enter(system_clock::now(), "c").has_value());
  release = true;
  waiter.join();
  EXPECT_TRUE(waited);
  EXPECT_EQ(admission.running(), 0u);
}

}  // namespace
}  // namespace relmap::session
