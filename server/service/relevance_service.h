// The gRPC handlers of relevance.v1.RelevanceService: each authorises the call
// (authorization.h), translates the request, delegates to the session layer and
// translates back.
#pragma once

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "perception/perception_config.h"
#include "relmap/v1/relevance_service.grpc.pb.h"
#include "service/authorization.h"
#include "service/metrics.h"
#include "session/intake/frame_intake.h"
#include "session/registry/session_registry.h"

namespace relmap::service {

// The service's limits, beyond the sessions' own.
struct ServiceLimits {
  perception::DecodeLimits decode;
  // Feature vectors in one ClassifyFeatures, AddSamples or ImportSession.
  std::size_t max_features_per_request = 100000;
  // Calls that process a cloud (session/intake/frame_admission.h): running at once,
  // waiting, and the longest wait before RESOURCE_EXHAUSTED.
  std::size_t concurrent_frames = 2;
  std::size_t queued_frames = 4;
  std::chrono::milliseconds max_frame_wait = session::FrameIntakeLimits{}.max_wait;
};

class RelevanceService final : public v1::RelevanceService::Service {
 public:
  // `admin_key_hash`: SHA-256 hex of the admin key that guards CreateSession,
  // ListSessions, DeleteSession and ImportSession, or empty for none.
  RelevanceService(session::SessionRegistry& registry, const ServiceLimits& limits,
                   std::string admin_key_hash = {})
      : registry_(registry),
        authorization_(registry, std::move(admin_key_hash)),
        max_features_per_request_(limits.max_features_per_request),
        intake_({.decode = limits.decode,
                 .concurrent = limits.concurrent_frames,
                 .queued = limits.queued_frames,
                 .max_wait = limits.max_frame_wait}) {}

  grpc::Status CreateSession(grpc::ServerContext* context, const v1::CreateSessionRequest* request,
                             v1::CreateSessionResponse* response) override;
  grpc::Status GetSession(grpc::ServerContext* context, const v1::GetSessionRequest* request,
                          v1::GetSessionResponse* response) override;
  grpc::Status ListSessions(grpc::ServerContext* context, const v1::ListSessionsRequest* request,
                            v1::ListSessionsResponse* response) override;
  grpc::Status DeleteSession(grpc::ServerContext* context, const v1::DeleteSessionRequest* request,
                             v1::DeleteSessionResponse* response) override;
  grpc::Status ComputeMaps(grpc::ServerContext* context, const v1::ComputeMapsRequest* request,
                           v1::ComputeMapsResponse* response) override;
  grpc::Status PostOutcome(grpc::ServerContext* context, const v1::PostOutcomeRequest* request,
                           v1::PostOutcomeResponse* response) override;
  grpc::Status ClassifyFeatures(grpc::ServerContext* context,
                                const v1::ClassifyFeaturesRequest* request,
                                v1::ClassifyFeaturesResponse* response) override;
  grpc::Status AddSamples(grpc::ServerContext* context, const v1::AddSamplesRequest* request,
                          v1::AddSamplesResponse* response) override;
  // The bound on the frame calls waiting for a slot (server/worker_sizing.h).
  void SetQueuedFrames(std::size_t queued) { intake_.admission().set_queue_bound(queued); }
  // Per-RPC counters and latencies, sessions and samples, in Prometheus's text format.
  std::string MetricsText() const;

  grpc::Status ExportSession(grpc::ServerContext* context, const v1::ExportSessionRequest* request,
                             v1::ExportSessionResponse* response) override;
  grpc::Status ImportSession(grpc::ServerContext* context, const v1::ImportSessionRequest* request,
                             v1::ImportSessionResponse* response) override;

 private:
  // Authorization::SessionFor; UNAVAILABLE (another server owns the session in a
  // shared store) gets a grpc-retry-pushback-ms trailer: nothing ran, and the
  // session is free once that server lets it go or dies.
  StatusOr<std::shared_ptr<session::Session>> Authorised(grpc::ServerContext& context,
                                                         const std::string& id) const;
  // A decoded cloud and its processing slot (session::FrameIntake), waiting at
  // most until the call's deadline. A busy server's RESOURCE_EXHAUSTED gets a
  // grpc-retry-pushback-ms trailer, the signal that the call did nothing and may
  // be repeated.
  StatusOr<session::AdmittedCloud> TakeCloud(grpc::ServerContext& context, const v1::Cloud& cloud,
                                             const std::string& session_id);

  session::SessionRegistry& registry_;
  const Authorization authorization_;
  const std::size_t max_features_per_request_;
  session::FrameIntake intake_;
  Metrics metrics_;
};

}  // namespace relmap::service
