// Which failures the client retries, how long it waits, and that a retried write
// keeps its request id — against an in-process server that fails on purpose.
#include "retry.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "client/reasoned_status.h"
#include "relevance_client.h"

namespace relmap::client {
namespace {

using std::chrono::milliseconds;
using testing::ReasonedStatus;

const grpc::Status kThreadpoolExhausted(grpc::StatusCode::RESOURCE_EXHAUSTED,
                                        "Server Threadpool Exhausted");

TEST(IsRetryable, AFullWorkerPoolIsRetriedForEveryCallBecauseNothingRan) {
  EXPECT_TRUE(IsRetryable(kThreadpoolExhausted, Idempotence::kIdempotent));
  EXPECT_TRUE(IsRetryable(kThreadpoolExhausted, Idempotence::kNotIdempotent));
}

TEST(IsRetryable, TheServersOwnResourceLimitsAreFinal) {
  const grpc::Status too_big(grpc::StatusCode::RESOURCE_EXHAUSTED, "cloud of 2000000 points");
  EXPECT_FALSE(IsRetryable(too_big, Idempotence::kIdempotent));
}

TEST(IsRetryable, ABusyAnswerWithAPushbackIsRetriedForEveryCall) {
  const grpc::Status busy(grpc::StatusCode::RESOURCE_EXHAUSTED, "busy: 2 clouds in progress");
  EXPECT_TRUE(IsRetryable(busy, Idempotence::kNotIdempotent, /*pushback=*/true));
}

TEST(IsRetryable, ABrokenConnectionIsRetriedOnlyForIdempotentCalls) {
  const grpc::Status unavailable(grpc::StatusCode::UNAVAILABLE, "connection reset");
  EXPECT_TRUE(IsRetryable(unavailable, Idempotence::kIdempotent));
  EXPECT_FALSE(IsRetryable(unavailable, Idempotence::kNotIdempotent));
}

TEST(IsRetryable, ASessionOwnedElsewhereWithAPushbackIsRetriedForEveryCall) {
  const grpc::Status owned(grpc::StatusCode::UNAVAILABLE, "session s is owned by server b");
  EXPECT_TRUE(IsRetryable(owned, Idempotence::kNotIdempotent, /*pushback=*/true));
}

TEST(IsRetryable, TheReasonsBusyAndSessionOwnedElsewhereAreRetriedForEveryCall) {
  // No pushback trailer, and messages that say nothing: the reason decides.
  EXPECT_TRUE(
      IsRetryable(ReasonedStatus(grpc::StatusCode::RESOURCE_EXHAUSTED, "cloud too big", "BUSY"),
                  Idempotence::kNotIdempotent));
  EXPECT_TRUE(
      IsRetryable(ReasonedStatus(grpc::StatusCode::UNAVAILABLE, "", "SESSION_OWNED_ELSEWHERE"),
                  Idempotence::kNotIdempotent));
}

TEST(IsRetryable, AFrameGoneIsAnAnswer) {
  EXPECT_FALSE(IsRetryable(ReasonedStatus(grpc::StatusCode::FAILED_PRECONDITION, "", "FRAME_GONE"),
                           Idempotence::kIdempotent));
}

TEST(IsRetryable, AnswersAreNeverRetried) {
  for (const auto code :
       {grpc::StatusCode::INVALID_ARGUMENT, grpc::StatusCode::NOT_FOUND,
        grpc::StatusCode::PERMISSION_DENIED, grpc::StatusCode::FAILED_PRECONDITION,
        grpc::StatusCode::DEADLINE_EXCEEDED}) {
    EXPECT_FALSE(IsRetryable(grpc::Status(code, ""), Idempotence::kIdempotent)) << code;
  }
}

TEST(IsFrameGone, IsTheReasonFrameGoneWhateverTheMessage) {
  EXPECT_TRUE(IsFrameGone(ReasonedStatus(grpc::StatusCode::FAILED_PRECONDITION,
                                         "frame 17 of session ab is unknown or no longer cached "
                                         "(the cache keeps the last 8 frames)",
                                         "FRAME_GONE")));
  EXPECT_TRUE(IsFrameGone(ReasonedStatus(grpc::StatusCode::FAILED_PRECONDITION,
                                         "session ab has learned samples already", "FRAME_GONE")));
}

TEST(IsFrameGone, IsNotTheMessageOfAFrameGoneWithoutTheReason) {
  EXPECT_FALSE(IsFrameGone(grpc::Status(grpc::StatusCode::FAILED_PRECONDITION,
                                        "frame 17 of session ab is unknown or no longer cached "
                                        "(the cache keeps the last 8 frames)")));
  EXPECT_FALSE(IsFrameGone(grpc::Status(grpc::StatusCode::FAILED_PRECONDITION,
                                        "session ab has learned samples already")));
  EXPECT_FALSE(IsFrameGone(grpc::Status(grpc::StatusCode::INVALID_ARGUMENT, "frame 17 has 3")));
  EXPECT_FALSE(
      IsFrameGone(ReasonedStatus(grpc::StatusCode::FAILED_PRECONDITION, "frame 17", "BUSY")));
}

TEST(BackoffBefore, DoublesFromTheInitialWaitUpToTheCapWithJitterAroundIt) {
  RetryPolicy policy;
  policy.initial_backoff = milliseconds(100);
  policy.max_backoff = milliseconds(1000);
  // A draw of 0.5 is a jitter factor of exactly 1.
  EXPECT_EQ(BackoffBefore(2, policy, 0.5), milliseconds(100));
  EXPECT_EQ(BackoffBefore(3, policy, 0.5), milliseconds(200));
  EXPECT_EQ(BackoffBefore(4, policy, 0.5), milliseconds(400));
  EXPECT_EQ(BackoffBefore(6, policy, 0.5), milliseconds(1000));  // 1600 capped
  // Factors 0.5 and 1.5 at the ends of the draw's range.
  EXPECT_EQ(BackoffBefore(3, policy, 0.0), milliseconds(100));
  EXPECT_EQ(BackoffBefore(3, policy, 0.999), milliseconds(299));
}

// Fails the first `failures` calls of each method with `failure`, then answers;
// records the request ids of PostOutcome and how many calls arrived.
class FlakyService final : public v1::RelevanceService::Service {
 public:
  // `pushback`: failures carry a grpc-retry-pushback-ms trailer of that many ms.
  FlakyService(int failures, grpc::Status failure, milliseconds delay = milliseconds(0),
               std::optional<int> pushback = std::nullopt)
      : failures_(failures), failure_(std::move(failure)), delay_(delay), pushback_(pushback) {}

  grpc::Status GetSession(grpc::ServerContext*, const v1::GetSessionRequest*,
                          v1::GetSessionResponse*) override {
    return Answer();
  }
  grpc::Status ComputeMaps(grpc::ServerContext* context, const v1::ComputeMapsRequest*,
                           v1::ComputeMapsResponse*) override {
    grpc::Status status = Answer();
    if (!status.ok() && pushback_) {
      context->AddTrailingMetadata("grpc-retry-pushback-ms", std::to_string(*pushback_));
    }
    return status;
  }
  grpc::Status PostOutcome(grpc::ServerContext*, const v1::PostOutcomeRequest* request,
                           v1::PostOutcomeResponse*) override {
    {
      std::lock_guard lock(mutex_);
      request_ids_.push_back(request->request_id());
    }
    return Answer();
  }

  int calls() const { return calls_.load(); }
  std::vector<std::string> request_ids() const {
    std::lock_guard lock(mutex_);
    return request_ids_;
  }

 private:
  grpc::Status Answer() {
    std::this_thread::sleep_for(delay_);
    return ++calls_ <= failures_ ? failure_ : grpc::Status::OK;
  }

  const int failures_;
  const grpc::Status failure_;
  const milliseconds delay_;
  const std::optional<int> pushback_;
  std::atomic<int> calls_{0};
  mutable std::mutex mutex_;
  std::vector<std::string> request_ids_;
};

class ClientAgainstFlakyServer : public ::testing::Test {
 protected:
  // The fixture owns the service, so that it outlives the server's shutdown in TearDown:
  // a call the client gave up on may still be running in it (UBSan found a test's local
  // service destroyed under a handler still sleeping in it).
  template <typename... Args>
  FlakyService& MakeService(Args&&... args) {
    return service_.emplace(std::forward<Args>(args)...);
  }
  void Start(FlakyService* service, ClientOptions options = {}) {
    grpc::ServerBuilder builder;
    int port = 0;
    builder.AddListeningPort("127.0.0.1:0", grpc::InsecureServerCredentials(), &port);
    builder.RegisterService(service);
    server_ = builder.BuildAndStart();
    ASSERT_NE(port, 0);
    options.address = "127.0.0.1:" + std::to_string(port);
    options.retry.initial_backoff = milliseconds(1);
    client_ = std::make_unique<RelevanceClient>(std::move(options));
  }
  void TearDown() override {
    if (server_) server_->Shutdown();
  }

  const SessionHandle session_{"s", "t"};
  std::optional<FlakyService> service_;  // declared before server_: destroyed after it
  std::unique_ptr<grpc::Server> server_;
  std::unique_ptr<RelevanceClient> client_;
};

TEST_F(ClientAgainstFlakyServer, RetriesAReadThroughABrokenConnection) {
  FlakyService& service = MakeService(2, grpc::Status(grpc::StatusCode::UNAVAILABLE, "reset"));
  Start(&service);
  v1::GetSessionResponse response;
  EXPECT_TRUE(client_->GetSession(session_, &response).ok());
  EXPECT_EQ(service.calls(), 3);
  EXPECT_EQ(client_->retries(), 2u);
}

TEST_F(ClientAgainstFlakyServer, DoesNotRepeatComputeMapsThatMayHaveRun) {
  FlakyService& service = MakeService(1, grpc::Status(grpc::StatusCode::UNAVAILABLE, "reset"));
  Start(&service);
  v1::ComputeMapsResponse response;
  EXPECT_EQ(client_->ComputeMaps(session_, v1::Cloud{}, &response).error_code(),
            grpc::StatusCode::UNAVAILABLE);
  EXPECT_EQ(service.calls(), 1);
}

TEST_F(ClientAgainstFlakyServer, RepeatsComputeMapsAfterABrokenConnectionWhenAskedTo) {
  FlakyService& service = MakeService(1, grpc::Status(grpc::StatusCode::UNAVAILABLE, "reset"));
  Start(&service);
  v1::ComputeMapsResponse response;
  EXPECT_TRUE(client_
                  ->ComputeMaps(session_, v1::Cloud{}, &response, client::PointLabels::kInclude,
                                client::MapsRepeat::kAfterBrokenConnection)
                  .ok());
  EXPECT_EQ(service.calls(), 2);
}

TEST_F(ClientAgainstFlakyServer, RepeatsComputeMapsThatABusyServerTurnedAway) {
  FlakyService& service = MakeService(2, kThreadpoolExhausted);
  Start(&service);
  v1::ComputeMapsResponse response;
  EXPECT_TRUE(client_->ComputeMaps(session_, v1::Cloud{}, &response).ok());
  EXPECT_EQ(service.calls(), 3);
}

TEST_F(ClientAgainstFlakyServer, WaitsOutTheServersPushbackBeforeRepeating) {
  FlakyService& service = MakeService(1, grpc::Status(grpc::StatusCode::RESOURCE_EXHAUSTED, "busy"),
                                      milliseconds(0), 150);
  Start(&service);
  v1::ComputeMapsResponse response;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(client_->ComputeMaps(session_, v1::Cloud{}, &response).ok());
  EXPECT_EQ(service.calls(), 2);
  EXPECT_GE(std::chrono::steady_clock::now() - start, milliseconds(150));
}

TEST_F(ClientAgainstFlakyServer, RepeatsWhatTheServerTurnedAwayAsBusyWithoutAPushback) {
  FlakyService& service =
      MakeService(2, ReasonedStatus(grpc::StatusCode::RESOURCE_EXHAUSTED, "busy", "BUSY"));
  Start(&service);
  v1::ComputeMapsResponse response;
  EXPECT_TRUE(client_->ComputeMaps(session_, v1::Cloud{}, &response).ok());
  EXPECT_EQ(service.calls(), 3);
}

TEST_F(ClientAgainstFlakyServer, ARetriedOutcomeKeepsOneGeneratedRequestId) {
  FlakyService& service = MakeService(2, grpc::Status(grpc::StatusCode::UNAVAILABLE, "reset"));
  Start(&service);
  v1::PostOutcomeResponse response;
  ASSERT_TRUE(client_->PostOutcome(session_, 1, 2, v1::LABEL_MOVEABLE, "", &response).ok());
  const std::vector<std::string> ids = service.request_ids();
  ASSERT_EQ(ids.size(), 3u);
  EXPECT_EQ(ids[0].size(), 32u);
  EXPECT_EQ(ids[1], ids[0]);
  EXPECT_EQ(ids[2], ids[0]);
}

TEST_F(ClientAgainstFlakyServer, GivesUpAfterTheAttemptLimit) {
  FlakyService& service = MakeService(100, grpc::Status(grpc::StatusCode::UNAVAILABLE, "down"));
  ClientOptions options;
  options.retry.max_attempts = 3;
  Start(&service, options);
  v1::GetSessionResponse response;
  EXPECT_EQ(client_->GetSession(session_, &response).error_code(), grpc::StatusCode::UNAVAILABLE);
  EXPECT_EQ(service.calls(), 3);
}

TEST_F(ClientAgainstFlakyServer, TheDeadlineBoundsTheWholeCall) {
  FlakyService& service = MakeService(0, grpc::Status::OK, milliseconds(300));
  ClientOptions options;
  options.deadline = milliseconds(50);
  Start(&service, options);
  v1::GetSessionResponse response;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(client_->GetSession(session_, &response).error_code(),
            grpc::StatusCode::DEADLINE_EXCEEDED);
  EXPECT_LT(std::chrono::steady_clock::now() - start, milliseconds(250));
}

}  // namespace
}  // namespace relmap::client
