// relmap-robot's loop: per iteration a cloud from the source, the maps, the target
// (refused outside the workspace), the push by the driver, the outcome posted — the
// driver's own label, else the after cloud for the server's change detector. Every
// iteration is recorded in the run directory when there is one.
#pragma once

#include <atomic>
#include <cstdio>
#include <optional>
#include <string>

#include "cloud_source.h"
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
  // One iteration with its retries; writes its status.
  Status Iterate(int iteration, RunSummary* summary);
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
