// The tcp-json driver against a fake robot controller on loopback: it answers, hangs,
// answers garbage, hangs up; and the driver reconnects.
#include "tcp_json_driver.h"

#include <gtest/gtest.h>

#include <thread>

#include "fake_controller.h"

namespace relmap::robot {
namespace {

using std::chrono::milliseconds;

DriverRequest Target(std::uint32_t supervoxel = 17) {
  DriverRequest target;
  target.set_session("s");
  target.set_frame(4);
  target.set_supervoxel(supervoxel);
  target.mutable_centroid()->set_z(0.8f);
  return target;
}

TcpJsonDriver Driver(const std::string& address, milliseconds reply_timeout = milliseconds(3000)) {
  return TcpJsonDriver(address, milliseconds(2000), reply_timeout);
}

TEST(TcpJsonDriver, SendsTheTargetAsOneLineOfTheExecDriversJsonAndReadsTheAnswer) {
  FakeController controller([](int, const std::string&) {
    return R"({"result": "done", "label": "moved", "message": "pushed 5 cm"})";
  });
  TcpJsonDriver driver = Driver(controller.address());
  StatusOr<PushOutcome> outcome = driver.Push(Target());
  ASSERT_TRUE(outcome.ok()) << outcome.status().message();
  EXPECT_EQ(outcome->result, PushResult::kDone);
  EXPECT_EQ(outcome->label, v1::LABEL_MOVEABLE);
  EXPECT_EQ(outcome->message, "pushed 5 cm");
  ASSERT_EQ(controller.lines().size(), 1u);
  EXPECT_EQ(controller.lines()[0], DriverRequestJson(Target()));
}

TEST(TcpJsonDriver, OneConnectionServesEveryPush) {
  FakeController controller([](int, const std::string&) { return R"({"result":"unreachable"})"; });
  TcpJsonDriver driver = Driver(controller.address());
  for (int push = 0; push < 3; ++push) {
    StatusOr<PushOutcome> outcome = driver.Push(Target());
    ASSERT_TRUE(outcome.ok()) << outcome.status().message();
    EXPECT_EQ(outcome->result, PushResult::kUnreachable);
  }
  EXPECT_EQ(driver.connections(), 1);
  EXPECT_EQ(controller.connections(), 1);
}

TEST(TcpJsonDriver, ASilentControllerIsATimeoutAndALateAnswerIsNeverTakenForTheNextPush) {
  // The first push is never answered; the second is answered with its supervoxel id.
  FakeController controller([](int request, const std::string& line) -> std::string {
    if (request == 1) return "";
    const bool second = line.find("\"supervoxel\":2") != std::string::npos;
    return std::string(R"({"result":"done","message":")") + (second ? "2" : "?") + "\"}";
  });
  TcpJsonDriver driver = Driver(controller.address(), milliseconds(300));
  const auto start = Clock::now();
  StatusOr<PushOutcome> hung = driver.Push(Target(1));
  ASSERT_FALSE(hung.ok());
  EXPECT_EQ(hung.status().code(), StatusCode::kDeadlineExceeded);
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(3));
  StatusOr<PushOutcome> next = driver.Push(Target(2));
  ASSERT_TRUE(next.ok()) << next.status().message();
  EXPECT_EQ(next->message, "2");
  EXPECT_EQ(driver.connections(), 2);
}

TEST(TcpJsonDriver, GarbageIsInvalidAndTheConnectionIsOpenedAgain) {
  FakeController controller([](int request, const std::string&) -> std::string {
    return request == 1 ? "pushed it, boss" : R"({"result":"done"})";
  });
  TcpJsonDriver driver = Driver(controller.address());
  StatusOr<PushOutcome> garbage = driver.Push(Target());
  ASSERT_FALSE(garbage.ok());
  EXPECT_EQ(garbage.status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(driver.Push(Target()).ok());
  EXPECT_EQ(controller.connections(), 2);
}

TEST(TcpJsonDriver, AHangUpBeforeTheAnswerIsUnavailableAndTheNextPushReconnects) {
  FakeController controller([](int request, const std::string&) -> std::string {
    return request == 1 ? FakeController::kHangUp : R"({"result":"done"})";
  });
  TcpJsonDriver driver = Driver(controller.address());
  StatusOr<PushOutcome> dropped = driver.Push(Target());
  ASSERT_FALSE(dropped.ok());
  EXPECT_EQ(dropped.status().code(), StatusCode::kUnavailable);
  EXPECT_TRUE(driver.Push(Target()).ok());
  EXPECT_EQ(controller.connections(), 2);
}

TEST(TcpJsonDriver, AConnectionTheControllerClosedBetweenPushesIsReplacedBeforeSending) {
  // The controller answers, then closes (a restart, say); the next push must not be
  // lost in the dead connection.
  FakeController controller([](int, const std::string&) -> std::string {
    return std::string(R"({"result":"done"})") + "\n" + FakeController::kHangUp;
  });
  TcpJsonDriver driver = Driver(controller.address());
  ASSERT_TRUE(driver.Push(Target()).ok());
  std::this_thread::sleep_for(milliseconds(100));
  StatusOr<PushOutcome> after_restart = driver.Push(Target());
  EXPECT_TRUE(after_restart.ok()) << after_restart.status().message();
  EXPECT_EQ(driver.connections(), 2);
}

TEST(TcpJsonDriver, NoControllerIsUnavailable) {
  std::string address;
  {
    StatusOr<UniqueFd> closed = ListenTcp("127.0.0.1:0");
    ASSERT_TRUE(closed.ok());
    address = "127.0.0.1:" + std::to_string(LocalPort(closed->get()));
  }  // nothing listens there any more
  TcpJsonDriver driver = Driver(address);
  StatusOr<PushOutcome> outcome = driver.Push(Target());
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.status().code(), StatusCode::kUnavailable);
}

}  // namespace
}  // namespace relmap::robot
