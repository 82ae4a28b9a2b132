// The exec driver with tiny shell scripts as the arm: good answers, crashes, hangs and
// garbage.
#include "exec_driver.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <fstream>

#include "integration/test_support.h"

namespace relmap::robot {
namespace {

using std::chrono::milliseconds;

class ExecDriverTest : public ::testing::Test {
 protected:
  // A driver running `body` as a /bin/sh script.
  ExecDriver Script(const std::string& body, milliseconds timeout = milliseconds(5000)) {
    const std::string path = directory_.path() + "/driver" + std::to_string(++scripts_) + ".sh";
    std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
    ::chmod(path.c_str(), 0755);
    return ExecDriver({path}, timeout);
  }

  static DriverRequest Target() {
    DriverRequest target;
    target.set_session("s");
    target.set_frame(4);
    target.set_supervoxel(17);
    target.mutable_centroid()->set_z(0.8f);
    return target;
  }

  relmap::testing::TemporaryDirectory directory_;
  int scripts_ = 0;
};

TEST_F(ExecDriverTest, ADoneAnswerWithoutLabelLeavesTheLabelToTheChangeDetector) {
  StatusOr<PushOutcome> outcome =
      Script(R"(cat > /dev/null; echo '{"result": "done", "message": "pushed"}')").Push(Target());
  ASSERT_TRUE(outcome.ok()) << outcome.status().message();
  EXPECT_EQ(outcome->result, PushResult::kDone);
  EXPECT_FALSE(outcome->label.has_value());
  EXPECT_EQ(outcome->message, "pushed");
}

TEST_F(ExecDriverTest, TheDriversOwnLabelIsKept) {
  StatusOr<PushOutcome> outcome =
      Script(R"(cat > /dev/null; echo '{"result":"done","label":"moved"}')").Push(Target());
  ASSERT_TRUE(outcome.ok()) << outcome.status().message();
  EXPECT_EQ(outcome->label, v1::LABEL_MOVEABLE);
}

TEST_F(ExecDriverTest, TheTargetArrivesAsOneJsonObjectOnStdin) {
  // The script answers with the supervoxel id it read, as the message.
  StatusOr<PushOutcome> outcome =
      Script(
          "id=$(sed -n 's/.*\"supervoxel\":\\([0-9]*\\).*/\\1/p')\n"
          "echo \"{\\\"result\\\":\\\"unreachable\\\",\\\"message\\\":\\\"$id\\\"}\"")
          .Push(Target());
  ASSERT_TRUE(outcome.ok()) << outcome.status().message();
  EXPECT_EQ(outcome->result, PushResult::kUnreachable);
  EXPECT_EQ(outcome->message, "17");
}

TEST_F(ExecDriverTest, ACrashIsAnError) {
  StatusOr<PushOutcome> outcome =
      Script(R"(echo '{"result":"done"}'; kill -SEGV $$)").Push(Target());
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.status().code(), StatusCode::kUnknown);
}

TEST_F(ExecDriverTest, ANonZeroExitIsAnErrorEvenWithAGoodAnswer) {
  StatusOr<PushOutcome> outcome = Script(R"(echo '{"result":"done"}'; exit 3)").Push(Target());
  ASSERT_FALSE(outcome.ok());
  EXPECT_NE(outcome.status().message().find("status 3"), std::string::npos);
}

TEST_F(ExecDriverTest, AHangIsKilledAtTheTimeout) {
  const auto start = std::chrono::steady_clock::now();
  StatusOr<PushOutcome> outcome = Script("sleep 30", milliseconds(300)).Push(Target());
  const auto took = std::chrono::steady_clock::now() - start;
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.status().code(), StatusCode::kDeadlineExceeded);
  // The sleep is a child of the shell: killing the process group ends it too, and the
  // driver does not wait for it.
  EXPECT_LT(took, std::chrono::seconds(5));
}

TEST_F(ExecDriverTest, GarbageIsAnError) {
  StatusOr<PushOutcome> outcome = Script("echo 'pushed it, boss'").Push(Target());
  ASSERT_FALSE(outcome.ok());
  EXPECT_EQ(outcome.status().code(), StatusCode::kInvalidArgument);
}

TEST_F(ExecDriverTest, AMissingProgramIsAnError) {
  ExecDriver driver({directory_.path() + "/no-such-driver"}, milliseconds(2000));
  EXPECT_FALSE(driver.Push(Target()).ok());
}

TEST(ParseDriverResult, RejectsUnknownResultsLabelsAndFields) {
  EXPECT_FALSE(ParseDriverResult(R"({"result":"maybe"})").ok());
  EXPECT_FALSE(ParseDriverResult(R"({"result":"done","label":"wobbled"})").ok());
  EXPECT_FALSE(ParseDriverResult(R"({"result":"done","lable":"moved"})").ok());
  EXPECT_FALSE(ParseDriverResult(R"({"result":"failed","label":"moved"})").ok());
  EXPECT_EQ(ParseDriverResult(R"({"result":"done","label":"still"})")->label,
            v1::LABEL_NOT_MOVEABLE);
}

TEST(MakeDriverRequest, TheApproachIsTheHorizontalViewingDirection) {
  v1::ComputeMapsResponse maps;
  maps.set_frame_id(9);
  v1::Supervoxel target;
  target.set_id(3);
  target.mutable_centroid()->set_x(0.3f);
  target.mutable_centroid()->set_y(0.2f);
  target.mutable_centroid()->set_z(0.4f);
  const DriverRequest request = MakeDriverRequest("s", maps, target, 1, 0);
  // (0.3, ·, 0.4) / 0.5: the y (down) part dropped.
  EXPECT_NEAR(request.approach().x(), 0.6, 1e-6);
  EXPECT_EQ(request.approach().y(), 0.0);
  EXPECT_NEAR(request.approach().z(), 0.8, 1e-6);
  EXPECT_EQ(request.frame(), 9u);
  EXPECT_EQ(request.supervoxel(), 3u);
}

}  // namespace
}  // namespace relmap::robot
