// FrameAdmission: at most `concurrent` calls run, at most `queued` wait, the rest are
// refused at once, and a waiter gives up at its deadline.
#include "session/frame_admission.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

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

}  // namespace
}  // namespace relmap::session
