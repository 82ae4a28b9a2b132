// 32 sessions driven at once, through one shared RelevanceClient, against a real
// relmap-server: no call of one session may show in another. The proof is a serial
// replay: each session's inputs, fed alone into a fresh session with the same
// seed, must give the same maps, targets and learned state, bit for bit.
#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <latch>
#include <string>
#include <thread>
#include <vector>

#include "integration/server_process.h"
#include "integration/test_support.h"
#include "relevance_client.h"

namespace relmap {
namespace {

constexpr int kSessions = 32;
// Session i runs kRounds + i % 2 rounds, so that odd sessions own a frame id that
// even ones never issued (frame ids count 1, 2, ... per session).
constexpr int kRounds = 4;
constexpr int kClouds = 4;
// 120×90 synthetic clouds: ~300 supervoxels, ~50 ms of server work each.
constexpr std::uint32_t kWidth = 120, kHeight = 90;

std::uint64_t SeedOf(int session) { return 1000 + static_cast<std::uint64_t>(session); }

// Each session has its own labelling of the world, so that a sample learned by the
// wrong session would change what that session predicts.
v1::Label LabelOf(int session, std::uint32_t supervoxel) {
  return (supervoxel + static_cast<std::uint32_t>(session)) % 2 == 0 ? v1::LABEL_MOVEABLE
                                                                     : v1::LABEL_NOT_MOVEABLE;
}

// "s<session>-r<round>", appended piece by piece: GCC 12 takes "s" + std::string
// for an overlapping memcpy (a false -Wrestrict).
std::string RequestId(int session, int round) {
  std::string id = "s";
  id += std::to_string(session);
  id += "-r";
  id += std::to_string(round);
  return id;
}

struct Outcome {
  std::uint32_t supervoxel = 0;
  v1::Label label = v1::LABEL_UNSPECIFIED;
  std::string request_id;
  v1::PostOutcomeResponse response;
};

struct Round {
  int cloud = 0;
  v1::ComputeMapsResponse maps;  // without its timings
  std::vector<Outcome> outcomes;
};

// One session's inputs and the server's answers.
struct SessionRun {
  client::SessionHandle session;
  std::vector<Round> rounds;
  v1::PostOutcomeResponse repeated;  // round 0's first outcome, posted again at the end
  std::string error;                 // the first failed call, or empty
};

// Counts the calls in flight at once, to show that the sessions did interleave.
struct Concurrency {
  std::atomic<int> in_flight = 0;
  std::atomic<int> most = 0;
  void Enter() {
    const int now = ++in_flight;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
  }
  void Leave() { --in_flight; }
};

// Runs session `index` on `run->session`: per round, ComputeMaps of one of `clouds`,
// then the outcomes of its target and of one more learnable supervoxel, labelled
// by LabelOf. With a `script`, the clouds and outcomes are the script's instead.
void Drive(client::RelevanceClient& client, int index, const std::vector<v1::Cloud>& clouds,
           const SessionRun* script, SessionRun* run, Concurrency* concurrency) {
  const auto call = [&](auto&& rpc) {
    if (concurrency != nullptr) concurrency->Enter();
    grpc::Status status = rpc();
    if (concurrency != nullptr) concurrency->Leave();
    return status;
  };
  const int rounds =
      script != nullptr ? static_cast<int>(script->rounds.size()) : kRounds + index % 2;
  for (int r = 0; r < rounds; ++r) {
    Round current;
    current.cloud = script != nullptr ? script->rounds[r].cloud : (index + r) % kClouds;
    const grpc::Status mapped = call(
        [&] { return client.ComputeMaps(run->session, clouds[current.cloud], &current.maps); });
    if (!mapped.ok()) {
      run->error = "round " + std::to_string(r) + " ComputeMaps: " + mapped.error_message();
      return;
    }
    current.maps.clear_timings();
    if (script != nullptr) {
      for (const Outcome& o : script->rounds[r].outcomes) {
        current.outcomes.push_back({o.supervoxel, o.label, o.request_id, {}});
      }
    } else {
      const std::uint32_t target = current.maps.target_supervoxel_id();
      current.outcomes.push_back({target, LabelOf(index, target), RequestId(index, r), {}});
      const auto count = static_cast<std::uint32_t>(current.maps.supervoxels_size());
      for (std::uint32_t k = 1; k < count; ++k) {
        const std::uint32_t other = (target + k + static_cast<std::uint32_t>(index)) % count;
        if (other != target && current.maps.supervoxels(static_cast<int>(other)).choice() > 0.0) {
          current.outcomes.push_back(
              {other, LabelOf(index, other), current.outcomes.front().request_id + "-other", {}});
          break;
        }
      }
    }
    for (Outcome& o : current.outcomes) {
      const grpc::Status posted = call([&] {
        return client.PostOutcome(run->session, current.maps.frame_id(), o.supervoxel, o.label,
                                  o.request_id, &o.response);
      });
      if (!posted.ok()) {
        run->error = "round " + std::to_string(r) + " PostOutcome: " + posted.error_message();
        return;
      }
    }
    run->rounds.push_back(std::move(current));
  }
  const Outcome& first = run->rounds.front().outcomes.front();
  const grpc::Status repeated = call([&] {
    return client.PostOutcome(run->session, run->rounds.front().maps.frame_id(), first.supervoxel,
                              first.label, first.request_id, &run->repeated);
  });
  if (!repeated.ok()) run->error = "repeated PostOutcome: " + repeated.error_message();
}

client::SessionHandle CreateSession(client::RelevanceClient& client, int index) {
  v1::SessionConfig config;
  config.set_seed(SeedOf(index));
  // LabelOf's labels do not depend on the features, so corrected's calibration
  // may rightly keep every prediction at ½ after a few samples; corrected_v1's
  // maps move with every sample, which is what a cross-talk check compares.
  config.mutable_classifier()->set_variant(v1::CLASSIFIER_VARIANT_CORRECTED_V1);
  client::SessionHandle session;
  const grpc::Status status = client.CreateSession(config, &session);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return session;
}

// "" if equal, else what differs.
std::string Difference(const google::protobuf::Message& a, const google::protobuf::Message& b) {
  std::string difference;
  google::protobuf::util::MessageDifferencer differencer;
  differencer.ReportDifferencesToString(&difference);
  return differencer.Compare(a, b) ? std::string() : difference;
}

v1::SessionState Exported(client::RelevanceClient& client, const client::SessionHandle& session) {
  v1::ExportSessionResponse response;
  const grpc::Status status = client.ExportSession(session, &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return response.state();
}

TEST(ConcurrentSessions, ThirtyTwoInterleavedSessionsMatchTheirSerialReplays) {
  // The server's worker pool answers RESOURCE_EXHAUSTED ("Server Threadpool
  // Exhausted") once --max-threads threads are busy: 16 by default, fewer than 32
  // callers plus gRPC's pollers. The client retries that answer with backoff
  // (client/retry.h), but its five attempts run out long before 32 ComputeMaps
  // queued on two cores drain: with the default pool some sessions fail. This
  // test is about cross-talk, not overload, so the pool takes every session at once.
  testing::ServerProcess server({"--max-threads", "128"});
  client::RelevanceClient client(server.address());
  std::vector<v1::Cloud> clouds;
  for (int c = 0; c < kClouds; ++c) {
    clouds.push_back(testing::PackedTabletop(kWidth, kHeight, static_cast<std::uint32_t>(c + 1)));
  }

  std::vector<SessionRun> runs(kSessions);
  for (int i = 0; i < kSessions; ++i) runs[i].session = CreateSession(client, i);
  Concurrency concurrency;
  {
    std::latch start(kSessions);
    std::vector<std::jthread> threads;
    for (int i = 0; i < kSessions; ++i) {
      threads.emplace_back([&, i] {
        start.arrive_and_wait();
        Drive(client, i, clouds, nullptr, &runs[i], &concurrency);
      });
    }
  }
  for (int i = 0; i < kSessions; ++i) ASSERT_EQ(runs[i].error, "") << "session " << i;
  EXPECT_GE(concurrency.most.load(), 4) << "the sessions hardly overlapped";

  // Each session counts exactly its own samples and frames; a repeated request id
  // was learned once.
  for (int i = 0; i < kSessions; ++i) {
    SCOPED_TRACE("session " + std::to_string(i));
    std::uint64_t moveable = 0, non_moveable = 0;
    for (const Round& played : runs[i].rounds) {
      for (const Outcome& o : played.outcomes) {
        (o.label == v1::LABEL_MOVEABLE ? moveable : non_moveable) += 1;
      }
    }
    v1::GetSessionResponse got;
    ASSERT_TRUE(client.GetSession(runs[i].session, &got).ok());
    EXPECT_EQ(got.stats().moveable_samples(), moveable);
    EXPECT_EQ(got.stats().non_moveable_samples(), non_moveable);
    EXPECT_EQ(got.stats().frames(), runs[i].rounds.size());
    EXPECT_EQ(got.config().seed(), SeedOf(i));
    const v1::PostOutcomeResponse& first = runs[i].rounds.front().outcomes.front().response;
    EXPECT_EQ(Difference(runs[i].repeated, first), "");
    // The maps that the replay compares are learned ones, not the flat prior.
    const auto& last = runs[i].rounds.back().maps.supervoxels();
    EXPECT_TRUE(std::any_of(last.begin(), last.end(),
                            [](const v1::Supervoxel& sv) { return sv.relevance() != 0.5; }));
  }

  // A frame id that only the odd session issued is not a frame of its even
  // neighbour: an error, and nothing learned.
  for (int i = 1; i < kSessions; i += 2) {
    const Round& last = runs[i].rounds.back();
    ASSERT_EQ(last.maps.frame_id(), static_cast<std::uint64_t>(kRounds + 1));
    const client::SessionHandle& neighbour = runs[i - 1].session;
    v1::GetSessionResponse before, after;
    ASSERT_TRUE(client.GetSession(neighbour, &before).ok());
    v1::PostOutcomeResponse response;
    const grpc::Status crossed =
        client.PostOutcome(neighbour, last.maps.frame_id(), last.outcomes.front().supervoxel,
                           v1::LABEL_MOVEABLE, "cross-" + std::to_string(i), &response);
    EXPECT_FALSE(crossed.ok()) << "session " << i - 1 << " took session " << i << "'s frame";
    EXPECT_TRUE(crossed.error_code() == grpc::StatusCode::FAILED_PRECONDITION ||
                crossed.error_code() == grpc::StatusCode::NOT_FOUND)
        << crossed.error_code() << " " << crossed.error_message();
    ASSERT_TRUE(client.GetSession(neighbour, &after).ok());
    EXPECT_EQ(Difference(after.stats(), before.stats()), "");
  }

  // The strongest check: each session's inputs replayed alone, one session at a
  // time, into a fresh session with the same seed on the same server.
  for (int i = 0; i < kSessions; ++i) {
    SCOPED_TRACE("session " + std::to_string(i));
    SessionRun replay;
    replay.session = CreateSession(client, i);
    Drive(client, i, clouds, &runs[i], &replay, nullptr);
    ASSERT_EQ(replay.error, "");
    ASSERT_EQ(replay.rounds.size(), runs[i].rounds.size());
    for (std::size_t r = 0; r < replay.rounds.size(); ++r) {
      const Round& concurrent = runs[i].rounds[r];
      const Round& alone = replay.rounds[r];
      EXPECT_EQ(Difference(alone.maps, concurrent.maps), "") << "round " << r;
      for (std::size_t k = 0; k < alone.outcomes.size(); ++k) {
        const v1::SessionStats& a = alone.outcomes[k].response.stats();
        const v1::SessionStats& c = concurrent.outcomes[k].response.stats();
        EXPECT_EQ(a.moveable_samples(), c.moveable_samples()) << "round " << r;
        EXPECT_EQ(a.non_moveable_samples(), c.non_moveable_samples()) << "round " << r;
        EXPECT_EQ(a.moveable_components(), c.moveable_components()) << "round " << r;
        EXPECT_EQ(a.non_moveable_components(), c.non_moveable_components()) << "round " << r;
      }
    }
    // Same samples (features bit for bit, labels, order), RNG and interactions.
    EXPECT_EQ(Difference(Exported(client, replay.session), Exported(client, runs[i].session)), "");
  }
  std::printf("calls in flight at most: %d; client retries: %llu\n", concurrency.most.load(),
              static_cast<unsigned long long>(client.retries()));
}

}  // namespace
}  // namespace relmap
