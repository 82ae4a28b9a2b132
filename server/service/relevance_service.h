// The gRPC handlers of relevance.v1.RelevanceService: each translates the request,
// checks the session token, delegates to the session layer and translates back.
#pragma once

#include <grpcpp/grpcpp.h>

#include <memory>
#include <string>

#include "perception/perception_config.h"
#include "relmap/v1/relevance_service.grpc.pb.h"
#include "service/metrics.h"
#include "session/session_registry.h"

namespace relmap::service {

class RelevanceService final : public v1::RelevanceService::Service {
 public:
  // `admin_key_hash`: SHA-256 hex of the admin key that guards CreateSession,
  // ListSessions and DeleteSession, or empty for none.
  RelevanceService(session::SessionRegistry& registry, perception::DecodeLimits limits,
                   std::size_t max_features_per_request, std::string admin_key_hash = {})
      : registry_(registry),
        limits_(limits),
        max_features_per_request_(max_features_per_request),
        admin_key_hash_(std::move(admin_key_hash)) {}

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
  // Per-RPC counters and latencies, sessions and samples, in Prometheus's text format.
  std::string MetricsText() const;

  grpc::Status ExportSession(grpc::ServerContext* context, const v1::ExportSessionRequest* request,
                             v1::ExportSessionResponse* response) override;
  grpc::Status ImportSession(grpc::ServerContext* context, const v1::ImportSessionRequest* request,
                             v1::ImportSessionResponse* response) override;

 private:
  // The session `id`, if the call's `authorization: Bearer <token>` matches it:
  // UNAUTHENTICATED without a bearer token, PERMISSION_DENIED with a wrong one,
  // NOT_FOUND for an unknown session.
  StatusOr<std::shared_ptr<session::Session>> Authorised(const grpc::ServerContext& context,
                                                         const std::string& id) const;

  // OK when no admin key is configured or the call's `x-relmap-admin-key`
  // matches; UNAUTHENTICATED without one, PERMISSION_DENIED with a wrong one.
  Status AdminAuthorised(const grpc::ServerContext& context) const;

  session::SessionRegistry& registry_;
  // RESOURCE_EXHAUSTED when a request carries more feature vectors than allowed.
  Status CheckFeatureCount(int count) const;

  const perception::DecodeLimits limits_;
  const std::size_t max_features_per_request_;
  const std::string admin_key_hash_;
  Metrics metrics_;
};

}  // namespace relmap::service
