// `kill -9` in the middle of the cloud loop: a client posts outcomes of a real
// cloud's targets, the server dies mid-call (a PostOutcome, or a ComputeMaps)
// and restarts on the same data directory. Every acknowledged outcome is still
// learned, at most the one in flight besides, and posting the same request ids
// again learns nothing more.
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "integration/server_process.h"
#include "integration/test_support.h"
#include "relevance_client.h"

namespace relmap {
namespace {

// Outcomes acknowledged before the kill: enough for both labels.
constexpr std::size_t kAcknowledgedBeforeKill = 4;

struct Posted {
  std::uint64_t frame_id = 0;
  std::uint32_t supervoxel = 0;
  v1::Label label = v1::LABEL_UNSPECIFIED;
  std::string request_id;
};

// The call the client's loop is making.
enum class Call { kComputeMaps, kPostOutcome };

// The client's loop on its own thread: ComputeMaps of the cloud, PostOutcome of
// the target, again, until a call fails. Every third outcome is "moveable".
class OutcomeLoop {
 public:
  OutcomeLoop(client::RelevanceClient& client, client::SessionHandle session, v1::Cloud cloud)
      : client_(client),
        session_(std::move(session)),
        cloud_(std::move(cloud)),
        thread_([this] { Run(); }) {}
  ~OutcomeLoop() {
    if (thread_.joinable()) thread_.join();
  }

  // Blocks until `acknowledged` outcomes are acknowledged and the loop has just
  // handed a `call` to the client, so that the caller acts while it is on the wire.
  void WaitUntilCalling(Call call, std::size_t acknowledged) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] {
      return finished_ || (acknowledged_.size() >= acknowledged && calling_ == call);
    });
  }

  // Waits for the loop to end (a call failed) and says how it went.
  struct Result {
    std::vector<Posted> acknowledged;
    std::optional<Posted> unacknowledged;  // posted, no answer: learned or not
    std::uint64_t last_frame_id = 0;
    grpc::Status failure;
  };
  Result Join() {
    thread_.join();
    std::lock_guard lock(mutex_);
    return {acknowledged_, in_flight_, last_frame_id_, failure_};
  }

 private:
  void Run() {
    for (int n = 0; n < 1000; ++n) {
      {
        std::lock_guard lock(mutex_);
        calling_ = Call::kComputeMaps;
      }
      changed_.notify_all();
      v1::ComputeMapsResponse maps;
      grpc::Status status = client_.ComputeMaps(session_, cloud_, &maps);
      if (!status.ok()) return Finish(status);
      const Posted post{maps.frame_id(), maps.target_supervoxel_id(),
                        n % 3 == 0 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE,
                        "crash-loop-" + std::to_string(n)};
      {
        std::lock_guard lock(mutex_);
        last_frame_id_ = maps.frame_id();
        in_flight_ = post;
        calling_ = Call::kPostOutcome;
      }
      changed_.notify_all();
      v1::PostOutcomeResponse response;
      status = client_.PostOutcome(session_, post.frame_id, post.supervoxel, post.label,
                                   post.request_id, &response);
      if (!status.ok()) return Finish(status);
      std::lock_guard lock(mutex_);
      acknowledged_.push_back(post);
      in_flight_.reset();
    }
    Finish({grpc::StatusCode::INTERNAL, "the server was never killed"});
  }

  void Finish(grpc::Status status) {
    {
      std::lock_guard lock(mutex_);
      failure_ = std::move(status);
      finished_ = true;
    }
    changed_.notify_all();
  }

  client::RelevanceClient& client_;
  const client::SessionHandle session_;
  const v1::Cloud cloud_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<Posted> acknowledged_;
  std::optional<Posted> in_flight_;
  std::optional<Call> calling_;
  std::uint64_t last_frame_id_ = 0;
  grpc::Status failure_;
  bool finished_ = false;
  std::thread thread_;  // last: starts once the members above exist
};

// Samples per label: [0] non-moveable, [1] moveable.
struct Counts {
  std::uint64_t of[2] = {0, 0};
  void Add(v1::Label label) { ++of[label == v1::LABEL_MOVEABLE ? 1 : 0]; }
};

Counts Stored(client::RelevanceClient& client, const client::SessionHandle& session) {
  v1::GetSessionResponse got;
  const grpc::Status status = client.GetSession(session, &got);
  EXPECT_TRUE(status.ok()) << status.error_message();
  Counts counts;
  counts.of[0] = got.stats().non_moveable_samples();
  counts.of[1] = got.stats().moveable_samples();
  return counts;
}

std::string CallName(const ::testing::TestParamInfo<Call>& call) {
  return call.param == Call::kComputeMaps ? "DuringComputeMaps" : "DuringPostOutcome";
}
void PrintTo(Call call, std::ostream* out) {
  *out << (call == Call::kComputeMaps ? "ComputeMaps" : "PostOutcome");
}

class KillMinusNine : public ::testing::TestWithParam<Call> {};

TEST_P(KillMinusNine, LosesNoAcknowledgedOutcomeOfTheCloudLoop) {
  const v1::Cloud cloud = client::PcdCloud(testing::ReadFile(RELMAP_REAL_CLOUD));
  const testing::TemporaryDirectory data;
  client::SessionHandle session;
  OutcomeLoop::Result before;
  {
    testing::ServerProcess server({"--data-dir", data.path()});
    client::RelevanceClient client(server.address());
    v1::SessionConfig config;
    config.set_seed(7);
    ASSERT_TRUE(client.CreateSession(config, &session).ok());
    OutcomeLoop loop(client, session, cloud);
    loop.WaitUntilCalling(GetParam(), kAcknowledgedBeforeKill);
    // A PostOutcome is killed as soon as it is sent (it commits within a
    // millisecond or two); a ComputeMaps of this cloud takes ~100 ms, so 20 ms
    // in, the server is busy with it.
    if (GetParam() == Call::kComputeMaps)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    server.Kill();
    before = loop.Join();
  }
  ASSERT_GE(before.acknowledged.size(), kAcknowledgedBeforeKill) << before.failure.error_message();
  EXPECT_FALSE(before.failure.ok());
  std::printf("killed with %zu outcomes acknowledged, %s; the loop's last call said %d: %s\n",
              before.acknowledged.size(),
              before.unacknowledged ? "one posted without an answer" : "none in flight",
              static_cast<int>(before.failure.error_code()),
              before.failure.error_message().c_str());
  Counts acknowledged, in_flight;
  for (const Posted& post : before.acknowledged) acknowledged.Add(post.label);
  if (before.unacknowledged) in_flight.Add(before.unacknowledged->label);

  testing::ServerProcess restarted({"--data-dir", data.path()});
  client::RelevanceClient client(restarted.address());
  const Counts stored = Stored(client, session);
  std::printf("after the restart the store holds %llu + %llu samples\n",
              static_cast<unsigned long long>(stored.of[0]),
              static_cast<unsigned long long>(stored.of[1]));
  for (int label = 0; label < 2; ++label) {
    SCOPED_TRACE(label == 1 ? "moveable" : "non-moveable");
    EXPECT_GE(stored.of[label], acknowledged.of[label]);
    EXPECT_LE(stored.of[label], acknowledged.of[label] + in_flight.of[label]);
  }

  // Frames live in memory only: a new outcome on the last frame is refused...
  v1::PostOutcomeResponse response;
  const grpc::Status stale = client.PostOutcome(session, before.last_frame_id, 0,
                                                v1::LABEL_MOVEABLE, "after-restart", &response);
  EXPECT_EQ(stale.error_code(), grpc::StatusCode::FAILED_PRECONDITION) << stale.error_message();
  // ...and frame ids go on after the stored count, so that no new frame takes the id
  // of an old one that a late outcome might name.
  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(client.ComputeMaps(session, cloud, &maps).ok());
  EXPECT_GT(maps.frame_id(), before.last_frame_id);

  // The same outcomes again, on their own (gone) frames: the restarted session
  // knows their request ids from the store and answers without learning them twice.
  for (const Posted& post : before.acknowledged) {
    const grpc::Status again = client.PostOutcome(session, post.frame_id, post.supervoxel,
                                                  post.label, post.request_id, &response);
    EXPECT_TRUE(again.ok()) << post.request_id << ": " << again.error_message();
    EXPECT_EQ(response.label(), post.label);
  }
  const Counts reposted = Stored(client, session);
  for (int label = 0; label < 2; ++label) EXPECT_EQ(reposted.of[label], stored.of[label]);

  // The one in flight, posted again: answered if the store had committed it; else
  // its frame is gone (FAILED_PRECONDITION: not recorded), and the client posts it
  // on a new frame of the same cloud. Either way it is learned exactly once.
  Counts expected = acknowledged;
  if (before.unacknowledged) {
    const Posted& post = *before.unacknowledged;
    grpc::Status again = client.PostOutcome(session, post.frame_id, post.supervoxel, post.label,
                                            post.request_id, &response);
    if (again.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
      again = client.PostOutcome(session, maps.frame_id(), post.supervoxel, post.label,
                                 post.request_id, &response);
    }
    EXPECT_TRUE(again.ok()) << again.error_message();
    expected.Add(post.label);
  }
  const Counts settled = Stored(client, session);
  for (int label = 0; label < 2; ++label) EXPECT_EQ(settled.of[label], expected.of[label]);

  // A new request id is still learned: the repeats above could have added samples.
  ASSERT_TRUE(client
                  .PostOutcome(session, maps.frame_id(), maps.target_supervoxel_id(),
                               v1::LABEL_MOVEABLE, "after-restart-new", &response)
                  .ok());
  EXPECT_EQ(response.stats().moveable_samples(), expected.of[1] + 1);
}

INSTANTIATE_TEST_SUITE_P(CrashRecovery, KillMinusNine,
                         ::testing::Values(Call::kPostOutcome, Call::kComputeMaps), CallName);

// Three push cycles on `session`: maps of `cloud`, then the target labelled by its
// parity. Returns the last maps.
v1::ComputeMapsResponse PushCycles(client::RelevanceClient& client,
                                   const client::SessionHandle& session, const v1::Cloud& cloud,
                                   int cycles) {
  v1::ComputeMapsResponse maps;
  for (int cycle = 0; cycle < cycles; ++cycle) {
    EXPECT_TRUE(client.ComputeMaps(session, cloud, &maps).ok());
    const std::uint32_t target = maps.target_supervoxel_id();
    v1::PostOutcomeResponse outcome;
    EXPECT_TRUE(client
                    .PostOutcome(session, maps.frame_id(), target,
                                 target % 2 == 0 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE,
                                 "cycle-" + std::to_string(cycle), &outcome)
                    .ok());
  }
  return maps;
}

TEST(CrashRecovery, ARestartedSessionMapsAndDrawsAsIfItNeverStopped) {
  const v1::Cloud cloud = testing::PackedTabletop(160, 120);
  const testing::TemporaryDirectory data;
  v1::SessionConfig config;
  config.set_seed(11);
  client::SessionHandle interrupted;
  {
    testing::ServerProcess server({"--data-dir", data.path()});
    client::RelevanceClient client(server.address());
    ASSERT_TRUE(client.CreateSession(config, &interrupted).ok());
    PushCycles(client, interrupted, cloud, 3);
    server.Kill();
  }
  testing::ServerProcess restarted({"--data-dir", data.path()});
  client::RelevanceClient client(restarted.address());
  v1::ComputeMapsResponse after_restart;
  ASSERT_TRUE(client.ComputeMaps(interrupted, cloud, &after_restart).ok());

  client::SessionHandle uninterrupted;
  ASSERT_TRUE(client.CreateSession(config, &uninterrupted).ok());
  PushCycles(client, uninterrupted, cloud, 3);
  v1::ComputeMapsResponse fourth;
  ASSERT_TRUE(client.ComputeMaps(uninterrupted, cloud, &fourth).ok());

  EXPECT_EQ(after_restart.frame_id(), 4u);
  EXPECT_EQ(after_restart.frame_id(), fourth.frame_id());
  EXPECT_EQ(after_restart.target_supervoxel_id(), fourth.target_supervoxel_id());
  ASSERT_EQ(after_restart.supervoxels_size(), fourth.supervoxels_size());
  for (int i = 0; i < fourth.supervoxels_size(); ++i) {
    EXPECT_EQ(after_restart.supervoxels(i).relevance(), fourth.supervoxels(i).relevance()) << i;
    EXPECT_EQ(after_restart.supervoxels(i).choice(), fourth.supervoxels(i).choice()) << i;
  }
}

}  // namespace
}  // namespace relmap
