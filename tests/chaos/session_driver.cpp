// The loop of one chaos session. A write is repeated with its request id until the
// server answers it, however many times the server dies meanwhile: the id is what
// keeps a repeat of an already committed write from being learned twice.
#include "chaos/session_driver.h"

#include <spdlog/spdlog.h>

#include <utility>

#include "grpc_status.h"

namespace relmap::chaos {
namespace {

constexpr std::chrono::milliseconds kPauseBeforeRepeat{100};

// Whether `status` leaves a write's fate open, or says it was not done: a broken or
// refused connection, a deadline, a busy or non-owning server, a transaction the
// store rolled back (ABORTED), an error a proxy made of a dying upstream (INTERNAL,
// UNKNOWN). Repeating the write with its request id is then what a robot does, and
// is harmless whatever happened to the first attempt. Every other code is the
// server's answer.
bool LeavesTheWriteOpen(const grpc::Status& status) {
  switch (status.error_code()) {
    case grpc::StatusCode::UNAVAILABLE:
    case grpc::StatusCode::DEADLINE_EXCEEDED:
    case grpc::StatusCode::RESOURCE_EXHAUSTED:
    case grpc::StatusCode::ABORTED:
    case grpc::StatusCode::INTERNAL:
    case grpc::StatusCode::UNKNOWN:
    case grpc::StatusCode::CANCELLED:
      return true;
    default:
      return client::IsRetryable(status, client::Idempotence::kIdempotent);
  }
}

// The supervoxel ComputeMaps drew as the target, or null.
const v1::Supervoxel* TargetOf(const v1::ComputeMapsResponse& maps) {
  if (!maps.has_target_supervoxel_id()) return nullptr;
  for (const v1::Supervoxel& supervoxel : maps.supervoxels()) {
    if (supervoxel.id() == maps.target_supervoxel_id()) return &supervoxel;
  }
  return nullptr;
}

bool NeverRefused(const grpc::Status& /*status*/) { return false; }

std::string CodeName(grpc::StatusCode code) {
  switch (code) {
    case grpc::StatusCode::UNAVAILABLE:
      return "UNAVAILABLE";
    case grpc::StatusCode::DEADLINE_EXCEEDED:
      return "DEADLINE_EXCEEDED";
    case grpc::StatusCode::RESOURCE_EXHAUSTED:
      return "RESOURCE_EXHAUSTED";
    case grpc::StatusCode::ABORTED:
      return "ABORTED";
    case grpc::StatusCode::INTERNAL:
      return "INTERNAL";
    case grpc::StatusCode::UNKNOWN:
      return "UNKNOWN";
    case grpc::StatusCode::CANCELLED:
      return "CANCELLED";
    default:
      return "code " + std::to_string(static_cast<int>(code));
  }
}

}  // namespace

SessionDriver::SessionDriver(DriverSettings settings, const v1::Cloud& cloud)
    : settings_(std::move(settings)),
      cloud_(cloud),
      client_(settings_.address),
      stream_(settings_.seed) {}

SessionDriver::~SessionDriver() { Stop(); }

Status SessionDriver::Start() {
  v1::SessionConfig config;
  config.set_seed(settings_.seed);
  const grpc::Status created = client_.CreateSession(config, &session_);
  if (!created.ok()) return client::FromGrpc(created, "CreateSession");
  spdlog::info("chaos session {} created session={}", settings_.index, session_.id);
  running_ = true;
  thread_ = std::thread([this] { Loop(); });
  return OkStatus();
}

void SessionDriver::Stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::map<std::string, std::uint64_t> SessionDriver::repeats() const {
  std::lock_guard lock(repeats_mutex_);
  return repeats_;
}

void SessionDriver::Loop() {
  for (std::uint64_t push = 0; !stop_; ++push) {
    if (!Push(push)) {
      spdlog::error("chaos session {} stopped session={}: {}", settings_.index, session_.id,
                    failure_.message());
      break;
    }
  }
  running_ = false;
}

bool SessionDriver::Push(std::uint64_t push) {
  v1::ComputeMapsResponse maps;
  const Answer mapped = Repeat(
      "ComputeMaps",
      [&] {
        maps.Clear();
        return client_.ComputeMaps(session_, cloud_, &maps, client::PointLabels::kOmit,
                                   client::MapsRepeat::kAfterBrokenConnection,
                                   client::SupervoxelFeatures::kInclude);
      },
      NeverRefused);
  if (mapped != Answer::kAcknowledged) return false;
  const v1::Supervoxel* target = TargetOf(maps);
  if (target == nullptr) {
    failure_ = InternalError("ComputeMaps answered without a target among its supervoxels");
    return false;
  }
  const std::string prefix = "chaos-" + std::to_string(settings_.index) + "-";

  // The outcome is stored as the target's feature with the label the client gives.
  v1::LabelledFeature outcome;
  outcome.set_label(push % 2 == 0 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
  *outcome.mutable_feature()->mutable_values() = target->features();
  const std::string outcome_id = prefix + "outcome-" + std::to_string(push);
  v1::PostOutcomeResponse posted;
  writing_ = true;
  const Answer outcome_answer = Repeat(
      "PostOutcome",
      [&] {
        return client_.PostOutcome(session_, maps.frame_id(), target->id(), outcome.label(),
                                   outcome_id, &posted);
      },
      client::IsFrameGone);
  writing_ = false;
  switch (outcome_answer) {
    case Answer::kAcknowledged:
      ledger_.Acknowledged(outcome);
      ++acknowledged_samples_;
      ++acknowledged_writes_;
      break;
    case Answer::kRefused:
      ledger_.Refused(outcome);
      break;
    case Answer::kNone:
      ledger_.Unsettled(outcome);
      return false;
  }

  v1::AddSamplesRequest batch;
  for (int i = 0; i < settings_.samples_per_batch; ++i) *batch.add_samples() = stream_.Next();
  batch.set_request_id(prefix + "samples-" + std::to_string(push));
  v1::AddSamplesResponse added;
  writing_ = true;
  const Answer samples_answer = Repeat(
      "AddSamples", [&] { return client_.AddSamples(session_, batch, &added); }, NeverRefused);
  writing_ = false;
  for (const v1::LabelledFeature& sample : batch.samples()) {
    if (samples_answer == Answer::kAcknowledged) {
      ledger_.Acknowledged(sample);
    } else {
      ledger_.Unsettled(sample);
    }
  }
  if (samples_answer != Answer::kAcknowledged) return false;
  acknowledged_samples_ += static_cast<std::uint64_t>(batch.samples_size());
  ++acknowledged_writes_;
  return true;
}

SessionDriver::Answer SessionDriver::Repeat(
    const char* what, const std::function<grpc::Status()>& call,
    const std::function<bool(const grpc::Status&)>& refused) {
  const auto give_up = std::chrono::steady_clock::now() + settings_.give_up;
  for (;;) {
    const grpc::Status status = call();
    if (status.ok()) return Answer::kAcknowledged;
    if (refused(status)) return Answer::kRefused;
    if (!LeavesTheWriteOpen(status)) {
      failure_ = client::FromGrpc(status, what);
      return Answer::kNone;
    }
    CountRepeat(status);
    if (std::chrono::steady_clock::now() >= give_up) {
      failure_ = client::FromGrpc(status, std::string(what) + " (no answer within " +
                                              std::to_string(settings_.give_up.count()) + " s)");
      return Answer::kNone;
    }
    std::this_thread::sleep_for(kPauseBeforeRepeat);
  }
}

void SessionDriver::CountRepeat(const grpc::Status& status) {
  std::lock_guard lock(repeats_mutex_);
  ++repeats_[CodeName(status.error_code())];
}

}  // namespace relmap::chaos
