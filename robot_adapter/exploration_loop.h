// relmap-robot's loop: per iteration a cloud from the source, the maps, the target
// (refused outside the workspace), the push by the driver, the outcome posted — the
// driver's own label, else the after cloud for the server's change detector. Every
// iteration is recorded in the run directory when there is one.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "cloud_source.h"
#include "iteration_state.h"
#include "pusher_driver.h"
#include "relevance_client.h"
#include "robot_messages.pb.h"

namespace relmap::robot {

struct RunSummary {
  int iterations = 0;  // ended (status.json written)
  int posted = 0;
  int skipped = 0;  // target outside the workspace
  int failed = 0;   // every attempt failed
  int dry_run = 0;
  int pushes = 0;        // sent to the driver, retries included
  bool stopped = false;  // by the stop flag
};

class ExplorationLoop {
 public:
  // All references outlive the loop. `stop`, when set, ends the run after the current
  // push has been posted (or left unposted); `progress` gets a line per iteration.
  ExplorationLoop(const RobotConfig& config, client::RelevanceClient& client, CloudSource& source,
                  PusherDriver& driver, const std::atomic<bool>* stop = nullptr,
                  std::FILE* progress = stderr);

  // Resumes config.session_id, else the run directory's session, else creates one
  // (recorded in the run directory: session.json, and session_token readable by the
  // owner only). FAILED_PRECONDITION when the run directory is another session's.
  Status Start();
  // Iterations until max_pushes, the source's end, max_iterations or the stop flag. A
  // restarted run continues after the last iteration its run directory ended.
  StatusOr<RunSummary> Run();

  const client::SessionHandle& session() const { return session_; }
  const std::string& run_id() const { return run_id_; }

 private:
  // An iteration as it goes: how it has ended so far, and what it recorded.
  struct Iteration {
    int number = 0;
    std::string directory;
    std::optional<IterationState> state;  // unset while no attempt has ended it
    std::string message;
    std::uint32_t attempts = 0;  // pushes sent to the driver
    bool started = false;        // a frame was taken: the iteration is recorded
    std::optional<double> accuracy;
    void End(IterationState ending, std::string why = {}) {
      state = ending;
      message = std::move(why);
    }
  };

  // One iteration with its retries; writes its status.
  Status Iterate(int number, RunSummary* summary);
  // One attempt: maps of the next frame, the target, the push, the outcome posted.
  // True when it ended the iteration; false to try again from a fresh frame.
  StatusOr<bool> Attempt(Iteration& iteration, int attempt, RunSummary* summary);
  // The maps of the next frame, recorded with the frame (and its truth, when the
  // source knows it); nullopt when the source has ended.
  StatusOr<std::optional<v1::ComputeMapsResponse>> MapNextFrame(Iteration& iteration);
  // The driver's request for the server's target, recorded; nullopt when there is
  // nothing to push (no target, outside the workspace, a dry run), which ends the
  // iteration.
  StatusOr<std::optional<DriverRequest>> ChooseTarget(Iteration& iteration,
                                                      const v1::ComputeMapsResponse& maps,
                                                      int attempt, RunSummary* summary);
  // Posts what a done push taught: the driver's label, else the after cloud.
  Status PostPushOutcome(Iteration& iteration, const v1::ComputeMapsResponse& maps,
                         const PushOutcome& pushed, RunSummary* summary);
  // Counts the ended iteration, writes its status.json and its progress line.
  Status Conclude(Iteration& iteration, RunSummary* summary);
  // The frame before the next push: the last after cloud (nothing moved since) or a
  // new capture; nullopt when the source has ended.
  StatusOr<std::optional<SourceFrame>> NextFrame();
  Status Record(const std::string& directory, const std::string& name,
                const google::protobuf::Message& message) const;
  Status RecordCloud(const std::string& directory, const std::string& stem,
                     const v1::Cloud& cloud) const;
  void Progress(int iteration, const IterationStatus& status, const RunSummary& summary,
                std::optional<double> accuracy) const;

  const RobotConfig& config_;
  client::RelevanceClient& client_;
  CloudSource& source_;
  PusherDriver& driver_;
  const std::atomic<bool>* stop_;
  std::FILE* progress_;
  client::SessionHandle session_;
  std::string run_id_;
  std::optional<SourceFrame> after_;
  bool source_ended_ = false;
};

// The PostOutcome request id of `iteration` of run `run_id`: the same after a restart,
// so that the server never learns an iteration twice.
std::string OutcomeRequestId(const std::string& run_id, int iteration);

}  // namespace relmap::robot
