// One completion queue, one thread: every session is a small state machine whose
// single outstanding operation (a call or a backoff alarm) has the session as tag.
#include "load_driver.h"

#include <grpcpp/alarm.h>
#include <grpcpp/grpcpp.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "common/random.h"
#include "outcome_label.h"
#include "retry.h"

namespace relmap::load {
namespace {

using Clock = std::chrono::steady_clock;

double MillisecondsBetween(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double, std::milli>(end - start).count();
}

// One session's loop and the state of its call in flight.
struct SessionLoop {
  enum class Step { kComputeMaps, kPostOutcome };

  SessionLoop(std::size_t position, const LoadSession& driven, const v1::Cloud& cloud)
      : index(position), session(driven), jitter(driven.seed) {
    // The cloud is copied once per session, not once per call.
    maps_request.set_session_id(session.handle.id);
    *maps_request.mutable_cloud() = cloud;
    outcome_request.set_session_id(session.handle.id);
  }

  const std::size_t index;
  const LoadSession session;
  Random jitter;

  v1::ComputeMapsRequest maps_request;
  v1::ComputeMapsResponse maps_response;
  v1::PostOutcomeRequest outcome_request;
  v1::PostOutcomeResponse outcome_response;

  Step step = Step::kComputeMaps;
  std::unique_ptr<grpc::ClientContext> context;
  std::unique_ptr<grpc::ClientAsyncResponseReader<v1::ComputeMapsResponse>> maps_call;
  std::unique_ptr<grpc::ClientAsyncResponseReader<v1::PostOutcomeResponse>> outcome_call;
  grpc::Status status;
  grpc::Alarm backoff;
  bool backing_off = false;
  int attempt = 1;               // of the current call
  Clock::time_point call_start;  // of its first attempt
  std::chrono::system_clock::time_point call_deadline;
  Clock::time_point cycle_start;
  std::uint64_t cycles_done = 0;
};

class Driver {
 public:
  Driver(v1::RelevanceService::Stub& stub, const LoadCloud& cloud, const LoadPlan& plan)
      : stub_(stub), cloud_(cloud), plan_(plan) {}

  LoadResults Run(const std::vector<LoadSession>& sessions,
                  const std::function<void(const LoadProgress&)>& progress) {
    std::vector<std::unique_ptr<SessionLoop>> loops;
    for (std::size_t i = 0; i < sessions.size(); ++i) {
      loops.push_back(std::make_unique<SessionLoop>(i, sessions[i], cloud_.cloud));
    }
    sessions_ = sessions.size();
    start_ = Clock::now();
    Clock::time_point last_answer = start_;
    for (auto& loop : loops) StartCycle(*loop);
    active_ = loops.size();

    auto next_report = start_ + std::chrono::seconds(1);
    void* tag = nullptr;
    bool ok = false;  // always true for a unary call's Finish and an alarm that fired
    while (active_ > 0) {
      const auto wait_until = std::chrono::system_clock::now() + std::chrono::milliseconds(200);
      if (queue_.AsyncNext(&tag, &ok, wait_until) == grpc::CompletionQueue::GOT_EVENT) {
        OnEvent(*static_cast<SessionLoop*>(tag));
        last_answer = Clock::now();
      }
      if (Clock::now() >= next_report) {
        progress(Progress());
        next_report += std::chrono::seconds(1);
      }
    }
    results_.elapsed_seconds = MillisecondsBetween(start_, last_answer) / 1000.0;
    progress(Progress());
    queue_.Shutdown();
    while (queue_.Next(&tag, &ok)) {
    }
    Average();
    return std::move(results_);
  }

 private:
  bool TimeIsUp() const {
    return plan_.seconds > 0 && MillisecondsBetween(start_, Clock::now()) >= plan_.seconds * 1000.0;
  }

  LoadProgress Progress() const {
    LoadProgress progress;
    progress.elapsed_seconds = MillisecondsBetween(start_, Clock::now()) / 1000.0;
    progress.cycles = results_.cycles;
    progress.calls = results_.compute_maps_ms.count() + results_.post_outcome_ms.count();
    progress.exhausted = results_.compute_maps_exhausted + results_.post_outcome_exhausted;
    const double by_cycles = plan_.cycles > 0 ? static_cast<double>(results_.cycles) /
                                                    static_cast<double>(plan_.cycles * sessions_)
                                              : 0.0;
    const double by_time = plan_.seconds > 0 ? progress.elapsed_seconds / plan_.seconds : 0.0;
    progress.fraction_done = std::min(1.0, std::max(by_cycles, by_time));
    return progress;
  }

  void StartCycle(SessionLoop& loop) {
    loop.cycle_start = Clock::now();
    StartCall(loop, SessionLoop::Step::kComputeMaps);
  }

  void StartCall(SessionLoop& loop, SessionLoop::Step step) {
    loop.step = step;
    loop.attempt = 1;
    loop.call_start = Clock::now();
    loop.call_deadline = std::chrono::system_clock::now() + plan_.deadline;
    StartAttempt(loop);
  }

  void StartAttempt(SessionLoop& loop) {
    loop.context = std::make_unique<grpc::ClientContext>();
    loop.context->AddMetadata("authorization", "Bearer " + loop.session.handle.token);
    loop.context->AddMetadata("x-relmap-session", loop.session.handle.id);
    loop.context->set_deadline(loop.call_deadline);
    if (loop.step == SessionLoop::Step::kComputeMaps) {
      loop.maps_call =
          stub_.PrepareAsyncComputeMaps(loop.context.get(), loop.maps_request, &queue_);
      loop.maps_call->StartCall();
      loop.maps_call->Finish(&loop.maps_response, &loop.status, &loop);
    } else {
      loop.outcome_call =
          stub_.PrepareAsyncPostOutcome(loop.context.get(), loop.outcome_request, &queue_);
      loop.outcome_call->StartCall();
      loop.outcome_call->Finish(&loop.outcome_response, &loop.status, &loop);
    }
  }

  // A finished call or an expired backoff of `loop`.
  void OnEvent(SessionLoop& loop) {
    if (loop.backing_off) {
      loop.backing_off = false;
      StartAttempt(loop);
      return;
    }
    const bool maps = loop.step == SessionLoop::Step::kComputeMaps;
    if (loop.status.ok()) {
      maps ? OnMaps(loop) : OnOutcome(loop);
      return;
    }
    // Only calls the server provably did not run are retried ("Server Threadpool
    // Exhausted", or a busy answer, reason BUSY with a pushback trailer, waited out at
    // least as long as it asks). Its other RESOURCE_EXHAUSTED answers (a cloud over the point
    // limit, too many sessions) are final, like every other error.
    const std::optional<std::chrono::milliseconds> pushback = client::PushbackOf(*loop.context);
    const auto retry_at =
        std::chrono::system_clock::now() +
        std::max(pushback.value_or(std::chrono::milliseconds(0)),
                 client::BackoffBefore(loop.attempt + 1, plan_.retry, loop.jitter.UniformUnit()));
    if (client::IsRetryable(loop.status, client::Idempotence::kNotIdempotent,
                            pushback.has_value()) &&
        loop.attempt < plan_.retry.max_attempts && retry_at < loop.call_deadline) {
      ++(maps ? results_.compute_maps_exhausted : results_.post_outcome_exhausted);
      ++loop.attempt;
      loop.backing_off = true;
      loop.backoff.Set(&queue_, retry_at, &loop);
      return;
    }
    Fail(loop, std::string(maps ? "ComputeMaps" : "PostOutcome") + " failed after " +
                   std::to_string(loop.attempt) + " attempt(s): code " +
                   std::to_string(static_cast<int>(loop.status.error_code())) + ", " +
                   loop.status.error_message());
  }

  void OnMaps(SessionLoop& loop) {
    const v1::ComputeMapsResponse& maps = loop.maps_response;
    results_.compute_maps_ms.Add(MillisecondsBetween(loop.call_start, Clock::now()));
    results_.server_compute_maps_ms.Add(maps.timings().total_ms());
    stage_sums_.admission_ms += maps.timings().admission_ms();
    stage_sums_.decode_ms += maps.timings().decode_ms();
    stage_sums_.filter_ms += maps.timings().filter_ms();
    stage_sums_.supervoxels_ms += maps.timings().supervoxels_ms();
    stage_sums_.features_ms += maps.timings().features_ms();
    stage_sums_.maps_ms += maps.timings().maps_ms();
    supervoxel_sum_ += static_cast<double>(maps.supervoxels_size());

    v1::Label label = v1::LABEL_UNSPECIFIED;
    if (cloud_.object_of_point.empty()) {
      label = CoinLabel(loop.session.seed, loop.cycles_done);
    } else if (const auto truth = GroundTruthLabel(maps, cloud_.object_of_point)) {
      label = *truth;
    } else {
      Fail(loop, "ComputeMaps returned " + std::to_string(maps.point_labels_size()) +
                     " point labels for a cloud of " +
                     std::to_string(cloud_.object_of_point.size()) + " points");
      return;
    }
    ++(label == v1::LABEL_MOVEABLE ? results_.moveable_labels : results_.not_moveable_labels);
    loop.outcome_request.set_frame_id(maps.frame_id());
    loop.outcome_request.set_supervoxel_id(maps.target_supervoxel_id());
    loop.outcome_request.set_label(label);
    // Deterministic, so that a retry is deduplicated by the server.
    loop.outcome_request.set_request_id("load-" + std::to_string(loop.index) + "-" +
                                        std::to_string(loop.cycles_done));
    StartCall(loop, SessionLoop::Step::kPostOutcome);
  }

  void OnOutcome(SessionLoop& loop) {
    const auto now = Clock::now();
    results_.post_outcome_ms.Add(MillisecondsBetween(loop.call_start, now));
    results_.cycle_ms.Add(MillisecondsBetween(loop.cycle_start, now));
    ++results_.cycles;
    ++loop.cycles_done;
    if ((plan_.cycles > 0 && loop.cycles_done >= plan_.cycles) || TimeIsUp()) {
      --active_;
    } else {
      StartCycle(loop);
    }
  }

  void Fail(SessionLoop& loop, const std::string& why) {
    if (results_.failed_sessions++ == 0) {
      results_.first_failure = "session " + std::to_string(loop.index) + ": " + why;
    }
    --active_;
  }

  void Average() {
    const auto n = static_cast<double>(results_.server_compute_maps_ms.count());
    if (n == 0) return;
    results_.server_stages = {stage_sums_.admission_ms / n, stage_sums_.decode_ms / n,
                              stage_sums_.filter_ms / n,    stage_sums_.supervoxels_ms / n,
                              stage_sums_.features_ms / n,  stage_sums_.maps_ms / n};
    results_.mean_supervoxels = supervoxel_sum_ / n;
  }

  v1::RelevanceService::Stub& stub_;
  const LoadCloud& cloud_;
  const LoadPlan plan_;
  grpc::CompletionQueue queue_;
  Clock::time_point start_;
  std::size_t sessions_ = 0;
  std::size_t active_ = 0;
  LoadResults results_;
  ServerStageMeans stage_sums_;
  double supervoxel_sum_ = 0;
};

}  // namespace

LoadResults RunLoad(v1::RelevanceService::Stub& stub, const std::vector<LoadSession>& sessions,
                    const LoadCloud& cloud, const LoadPlan& plan,
                    const std::function<void(const LoadProgress&)>& progress) {
  return Driver(stub, cloud, plan).Run(sessions, progress);
}

}  // namespace relmap::load
