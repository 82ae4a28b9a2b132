// The C++ client of the relevance server: one object per server connection,
// session calls authorised with the session's token. Errors come back as the
// server's gRPC status.
#pragma once

#include <grpcpp/grpcpp.h>

#include <memory>
#include <string>

#include "relmap/v1/relevance_service.grpc.pb.h"

namespace relmap::client {

// A session as the client holds it.
struct SessionHandle {
  std::string id;
  std::string token;
};

class RelevanceClient {
 public:
  // Connects to `address` (host:port), insecure, with `max_message_bytes` for
  // clouds in both directions.
  explicit RelevanceClient(const std::string& address, int max_message_bytes = 64 << 20);

  grpc::Status CreateSession(const v1::SessionConfig& config, SessionHandle* session,
                             v1::CreateSessionResponse* response = nullptr);
  grpc::Status GetSession(const SessionHandle& session, v1::GetSessionResponse* response);
  grpc::Status ListSessions(v1::ListSessionsResponse* response);
  grpc::Status DeleteSession(const SessionHandle& session);
  grpc::Status ComputeMaps(const SessionHandle& session, const v1::Cloud& cloud,
                           v1::ComputeMapsResponse* response);
  grpc::Status PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                           std::uint32_t supervoxel_id, v1::Label label,
                           const std::string& request_id, v1::PostOutcomeResponse* response);
  // The outcome as the cloud after the push: the server's change detector labels it.
  grpc::Status PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                           std::uint32_t supervoxel_id, const v1::Cloud& after_cloud,
                           const std::string& request_id, v1::PostOutcomeResponse* response);

  // The admin key sent with CreateSession, ListSessions and DeleteSession, for
  // servers started with one.
  void set_admin_key(std::string key) { admin_key_ = std::move(key); }

  v1::RelevanceService::Stub& stub() { return *stub_; }

 private:
  // A context for a call on `session`: its bearer token, and its id as
  // x-relmap-session for load balancers that route by session.
  static void Authorise(grpc::ClientContext& context, const SessionHandle& session);

  void AddAdminKey(grpc::ClientContext& context) const;
  // A PostOutcomeRequest without its outcome, and sending one.
  static v1::PostOutcomeRequest OutcomeRequest(const SessionHandle& session, std::uint64_t frame_id,
                                               std::uint32_t supervoxel_id,
                                               const std::string& request_id);
  grpc::Status SendOutcome(const SessionHandle& session, const v1::PostOutcomeRequest& request,
                           v1::PostOutcomeResponse* response);

  std::unique_ptr<v1::RelevanceService::Stub> stub_;
  std::string admin_key_;
};

// A cloud message carrying the bytes of a PCD file.
v1::Cloud PcdCloud(std::string pcd_bytes);

}  // namespace relmap::client
