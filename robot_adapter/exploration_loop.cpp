// The exploration loop of relmap-robot.
#include "exploration_loop.h"

#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

#include "grpc_status.h"
#include "map_accuracy.h"
#include "robot_config.h"
#include "run_record.h"

namespace relmap::robot {
namespace fs = std::filesystem;
namespace {

const v1::Supervoxel* FindSupervoxel(const v1::ComputeMapsResponse& maps, std::uint32_t id) {
  for (const v1::Supervoxel& supervoxel : maps.supervoxels()) {
    if (supervoxel.id() == id) return &supervoxel;
  }
  return nullptr;
}

DriverResult AsRecord(const StatusOr<PushOutcome>& outcome) {
  DriverResult record;
  if (!outcome.ok()) {
    record.set_result("error");
    record.set_message(outcome.status().message());
    return record;
  }
  record.set_result(PushResultName(outcome->result));
  if (outcome->label) record.set_label(*outcome->label == v1::LABEL_MOVEABLE ? "moved" : "still");
  record.set_message(outcome->message);
  return record;
}

std::string SessionTokenPath(const std::string& run_dir) { return run_dir + "/session_token"; }

}  // namespace

std::string OutcomeRequestId(const std::string& run_id, int iteration) {
  return run_id + "/" + std::to_string(iteration);
}

ExplorationLoop::ExplorationLoop(const RobotConfig& config, client::RelevanceClient& client,
                                 CloudSource& source, PusherDriver& driver,
                                 const std::atomic<bool>* stop, std::FILE* progress)
    : config_(config),
      client_(client),
      source_(source),
      driver_(driver),
      stop_(stop),
      progress_(progress) {}

Status ExplorationLoop::Start() {
  const std::string& run_dir = config_.run_dir();
  RunSession recorded;
  const bool has_record = !run_dir.empty() && ReadJson(run_dir + "/session.json", &recorded).ok();
  if (has_record && !config_.session_id().empty() &&
      recorded.session_id() != config_.session_id()) {
    return FailedPreconditionError(run_dir + " records a run of session " + recorded.session_id() +
                                   ", not of " + config_.session_id());
  }
  if (!config_.session_id().empty()) {
    session_.id = config_.session_id();
    session_.token = config_.session_token();
    if (const char* token = std::getenv("RELMAP_SESSION_TOKEN"); session_.token.empty() && token) {
      session_.token = token;
    }
  } else if (has_record) {
    session_.id = recorded.session_id();
    std::ifstream in(SessionTokenPath(run_dir));
    session_.token.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } else {
    if (Status status =
            client::FromGrpc(client_.CreateSession(config_.session(), &session_), "CreateSession");
        !status.ok()) {
      return status;
    }
  }
  // The session must exist and the token fit: GetSession checks both.
  v1::GetSessionResponse current;
  if (Status status = client::FromGrpc(client_.GetSession(session_, &current), "GetSession");
      !status.ok()) {
    return status;
  }
  run_id_ = !config_.run_id().empty()                  ? config_.run_id()
            : has_record && !recorded.run_id().empty() ? recorded.run_id()
                                                       : client::RandomRequestId();
  if (run_dir.empty() || has_record) return OkStatus();
  recorded.set_session_id(session_.id);
  recorded.set_run_id(run_id_);
  *recorded.mutable_config() = current.config();
  if (Status status = WriteJson(run_dir + "/session.json", recorded); !status.ok()) return status;
  if (Status status = WriteFile(SessionTokenPath(run_dir), session_.token); !status.ok()) {
    return status;
  }
  ::chmod(SessionTokenPath(run_dir).c_str(), S_IRUSR | S_IWUSR);
  return OkStatus();
}

StatusOr<RunSummary> ExplorationLoop::Run() {
  RunSummary summary;
  // A restart continues after the last iteration that ended; one cut short is redone
  // under its own number, so its request id is unchanged.
  int iteration = 1;
  if (!config_.run_dir().empty()) {
    for (int recorded : RecordedIterations(config_.run_dir())) {
      const bool ended =
          fs::exists(IterationDirectory(config_.run_dir(), recorded) + "/status.json");
      iteration = ended ? recorded + 1 : recorded;
    }
  }
  for (int done = 0; done < static_cast<int>(config_.max_iterations()); ++done, ++iteration) {
    if (stop_ != nullptr && stop_->load()) {
      summary.stopped = true;
      break;
    }
    if (summary.pushes + summary.dry_run >= static_cast<int>(config_.max_pushes())) break;
    if (Status status = Iterate(iteration, &summary); !status.ok()) return status;
    if (source_ended_) break;
  }
  if (stop_ != nullptr && stop_->load()) summary.stopped = true;
  return summary;
}

StatusOr<std::optional<SourceFrame>> ExplorationLoop::NextFrame() {
  if (after_) {
    std::optional<SourceFrame> frame = std::move(after_);
    after_.reset();
    return frame;
  }
  return source_.Next();
}

Status ExplorationLoop::Record(const std::string& directory, const std::string& name,
                               const google::protobuf::Message& message) const {
  if (config_.run_dir().empty()) return OkStatus();
  return WriteJson(directory + "/" + name, message);
}

Status ExplorationLoop::RecordCloud(const std::string& directory, const std::string& stem,
                                    const v1::Cloud& cloud) const {
  if (config_.run_dir().empty()) return OkStatus();
  return WriteCloud(directory, stem, cloud);
}

Status ExplorationLoop::Iterate(int number, RunSummary* summary) {
  Iteration iteration;
  iteration.number = number;
  iteration.directory = IterationDirectory(config_.run_dir(), number);
  for (int attempt = 0; attempt <= static_cast<int>(config_.retries()); ++attempt) {
    if (stop_ != nullptr && stop_->load()) {
      iteration.state = IterationState::kStopped;
      break;
    }
    if (summary->pushes >= static_cast<int>(config_.max_pushes())) break;
    StatusOr<bool> ended = Attempt(iteration, attempt, summary);
    if (!ended.ok()) return ended.status();
    if (*ended) break;
  }
  if (!iteration.started) return OkStatus();
  return Conclude(iteration, summary);
}

StatusOr<bool> ExplorationLoop::Attempt(Iteration& iteration, int attempt, RunSummary* summary) {
  StatusOr<std::optional<v1::ComputeMapsResponse>> mapped = MapNextFrame(iteration);
  if (!mapped.ok()) return mapped.status();
  if (!mapped->has_value()) {
    source_ended_ = true;
    iteration.End(attempt == 0 ? IterationState::kStopped : IterationState::kFailed,
                  "the source has no more clouds");
    return true;
  }
  const v1::ComputeMapsResponse& maps = **mapped;
  StatusOr<std::optional<DriverRequest>> request = ChooseTarget(iteration, maps, attempt, summary);
  if (!request.ok()) return request.status();
  if (!request->has_value()) return true;  // nothing to push
  ++summary->pushes;
  ++iteration.attempts;
  const StatusOr<PushOutcome> pushed = driver_.Push(**request);
  if (Status s = Record(iteration.directory, "driver.json", AsRecord(pushed)); !s.ok()) return s;
  if (!pushed.ok() || pushed->result != PushResult::kDone) {
    // Nothing is learned from a push that did not happen; the next attempt starts
    // from a fresh frame (a failed push may have disturbed the scene).
    iteration.End(IterationState::kFailed,
                  pushed.ok() ? std::string(PushResultName(pushed->result)) + ": " + pushed->message
                              : pushed.status().message());
    return false;
  }
  if (Status s = PostPushOutcome(iteration, maps, *pushed, summary); !s.ok()) return s;
  return true;
}

StatusOr<std::optional<v1::ComputeMapsResponse>> ExplorationLoop::MapNextFrame(
    Iteration& iteration) {
  StatusOr<std::optional<SourceFrame>> frame = NextFrame();
  if (!frame.ok()) return frame.status();
  if (!frame->has_value()) return std::optional<v1::ComputeMapsResponse>();
  iteration.started = true;
  const SourceFrame& before = **frame;
  v1::ComputeMapsResponse maps;
  const client::PointLabels labels =
      before.truth ? client::PointLabels::kInclude : client::PointLabels::kOmit;
  if (Status s = client::FromGrpc(client_.ComputeMaps(session_, before.cloud, &maps, labels,
                                                      client::MapsRepeat::kAfterBrokenConnection),
                                  "ComputeMaps");
      !s.ok()) {
    return s;
  }
  if (before.truth) {
    StatusOr<std::vector<bool>> truth = before.truth(maps);
    if (!truth.ok()) return truth.status();
    iteration.accuracy = MapAccuracy(maps, *truth);
    IterationTruth record;
    for (bool moveable : *truth) record.add_moveable(moveable);
    if (Status s = Record(iteration.directory, "truth.json", record); !s.ok()) return s;
  }
  maps.clear_point_labels();
  if (Status s = RecordCloud(iteration.directory, "before", before.cloud); !s.ok()) return s;
  if (Status s = Record(iteration.directory, "maps.json", maps); !s.ok()) return s;
  return std::optional<v1::ComputeMapsResponse>(std::move(maps));
}

StatusOr<std::optional<DriverRequest>> ExplorationLoop::ChooseTarget(
    Iteration& iteration, const v1::ComputeMapsResponse& maps, int attempt, RunSummary* summary) {
  if (!maps.has_target_supervoxel_id()) {
    iteration.End(IterationState::kNoTarget, "no supervoxel with usable features");
    return std::optional<DriverRequest>();
  }
  const v1::Supervoxel* target = FindSupervoxel(maps, maps.target_supervoxel_id());
  if (target == nullptr) return InternalError("the server's target is not among its supervoxels");
  DriverRequest request = MakeDriverRequest(session_.id, maps, *target, iteration.number, attempt);
  if (Status s = Record(iteration.directory, "target.json", request); !s.ok()) return s;
  if (config_.has_workspace() && !InWorkspace(config_.workspace(), request.centroid().x(),
                                              request.centroid().y(), request.centroid().z())) {
    iteration.End(IterationState::kSkipped,
                  "target outside the workspace box; not sent to the driver");
    ++summary->skipped;
    return std::optional<DriverRequest>();
  }
  if (config_.dry_run()) {
    std::cout << DriverRequestJson(request) << std::endl;
    iteration.state = IterationState::kDryRun;  // the message stays as it was
    ++summary->dry_run;
    return std::optional<DriverRequest>();
  }
  return std::optional<DriverRequest>(std::move(request));
}

Status ExplorationLoop::PostPushOutcome(Iteration& iteration, const v1::ComputeMapsResponse& maps,
                                        const PushOutcome& pushed, RunSummary* summary) {
  v1::PostOutcomeResponse posted;
  const std::string request_id = OutcomeRequestId(run_id_, iteration.number);
  const std::uint32_t target = maps.target_supervoxel_id();
  grpc::Status answer;
  if (pushed.label) {
    answer =
        client_.PostOutcome(session_, maps.frame_id(), target, *pushed.label, request_id, &posted);
  } else {
    StatusOr<std::optional<SourceFrame>> after = source_.Next();
    if (!after.ok()) return after.status();
    if (!after->has_value()) {
      source_ended_ = true;
      iteration.End(IterationState::kFailed,
                    "pushed, but the source has no after cloud: nothing posted");
      return OkStatus();
    }
    if (Status s = RecordCloud(iteration.directory, "after", (*after)->cloud); !s.ok()) return s;
    answer = client_.PostOutcome(session_, maps.frame_id(), target, (*after)->cloud, request_id,
                                 &posted);
    after_ = std::move(*after);
  }
  if (client::IsFrameGone(answer)) {
    // The push is done but cannot be learned; the next iteration starts from new maps.
    iteration.End(IterationState::kFailed,
                  "pushed, but the server no longer has the frame: " + answer.error_message());
    return OkStatus();
  }
  if (Status s = client::FromGrpc(answer, "PostOutcome"); !s.ok()) return s;
  if (Status s = Record(iteration.directory, "label.json", posted); !s.ok()) return s;
  iteration.End(IterationState::kPosted, posted.label() == v1::LABEL_MOVEABLE ? "moved" : "still");
  ++summary->posted;
  return OkStatus();
}

Status ExplorationLoop::Conclude(Iteration& iteration, RunSummary* summary) {
  if (iteration.state == IterationState::kFailed) ++summary->failed;
  if (!iteration.state) iteration.End(IterationState::kStopped, "max_pushes reached");
  ++summary->iterations;
  IterationStatus status;
  status.set_state(std::string(IterationStateName(*iteration.state)));
  status.set_message(iteration.message);
  status.set_attempts(iteration.attempts);
  if (Status s = Record(iteration.directory, "status.json", status); !s.ok()) return s;
  Progress(iteration.number, status, *summary, iteration.accuracy);
  return OkStatus();
}

void ExplorationLoop::Progress(int iteration, const IterationStatus& status,
                               const RunSummary& summary, std::optional<double> accuracy) const {
  if (progress_ == nullptr) return;
  std::string line = "iteration " + std::to_string(iteration) + ": " + status.state();
  if (!status.message().empty()) line += " (" + status.message() + ")";
  // A dry run's printed targets stand for its pushes.
  const int pushes = config_.dry_run() ? summary.dry_run : summary.pushes;
  line += ", pushes " + std::to_string(pushes) + "/" + std::to_string(config_.max_pushes()) +
          ", posted " + std::to_string(summary.posted);
  if (accuracy) {
    char score[32];
    std::snprintf(score, sizeof score, ", map accuracy %.3f", *accuracy);
    line += score;
  }
  std::fprintf(progress_, "%s\n", line.c_str());
  std::fflush(progress_);
}

}  // namespace relmap::robot
