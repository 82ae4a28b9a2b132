// The C++ client of the relevance server: one object per server connection, safe to
// share between threads. Session calls are authorised with the session's token; every
// call has a deadline; calls the server provably did not run, and idempotent calls
// that met a broken connection, are retried with backoff (retry.h). Errors come back
// as the server's gRPC status, whose reason (error_reason.h) is what to decide by.
#pragma once

#include <grpcpp/grpcpp.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "client_options.h"
#include "error_reason.h"
#include "grpc/health/v1/health.pb.h"
#include "relmap/v1/relevance_service.grpc.pb.h"
#include "retry.h"

namespace relmap::client {

// Whether ComputeMaps answers with the label of every point (for renderings) or
// only with the supervoxels and the target (a third of the bytes for a Kinect frame).
enum class PointLabels { kInclude, kOmit };

// Whether ComputeMaps is repeated after a broken connection (UNAVAILABLE), when the
// server may or may not have computed the frame. Never, by default: a repeat after
// a frame that was computed draws another target, so the session's frame ids and
// draws skip one and a seeded run no longer replays bit for bit. A client that would
// rather lose a frame than stop (a robot or simulator behind a load balancer, whose
// server may die mid-call) repeats it: the call then lands on the next server.
enum class MapsRepeat { kNever, kAfterBrokenConnection };

// Whether ComputeMaps answers with each supervoxel's 48 feature values
// (Supervoxel.features; for exporting datasets), or without (the default).
enum class SupervoxelFeatures { kOmit, kInclude };

// A session as the client holds it.
struct SessionHandle {
  std::string id;
  std::string token;
};

class RelevanceClient {
 public:
  explicit RelevanceClient(ClientOptions options);
  // Plaintext to `address` (host:port) with the default deadline and retries.
  explicit RelevanceClient(const std::string& address, int max_message_bytes = 64 << 20);

  grpc::Status CreateSession(const v1::SessionConfig& config, SessionHandle* session,
                             v1::CreateSessionResponse* response = nullptr);
  grpc::Status GetSession(const SessionHandle& session, v1::GetSessionResponse* response);
  // Every session, following the pages; the answer has no next_page_token.
  grpc::Status ListSessions(v1::ListSessionsResponse* response);
  // One page, as the request asks.
  grpc::Status ListSessionsPage(const v1::ListSessionsRequest& request,
                                v1::ListSessionsResponse* response);
  grpc::Status DeleteSession(const SessionHandle& session);
  grpc::Status ComputeMaps(const SessionHandle& session, const v1::Cloud& cloud,
                           v1::ComputeMapsResponse* response,
                           PointLabels point_labels = PointLabels::kInclude,
                           MapsRepeat repeat = MapsRepeat::kNever,
                           SupervoxelFeatures features = SupervoxelFeatures::kOmit);
  // PostOutcome and AddSamples are deduplicated by the server on `request_id`; an
  // empty one is replaced by a fresh random id, so that these calls are always safe
  // to retry. Pass your own to make a repeat after a client crash harmless too.
  // `moved_with_target`: other supervoxels the push moved with the target, each learned
  // as moveable (PostOutcomeRequest.moved_supervoxels); `same_object`: the rest of the
  // target's rigid object, learned with `label` (PostOutcomeRequest.object_supervoxels).
  grpc::Status PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                           std::uint32_t supervoxel_id, v1::Label label,
                           const std::string& request_id, v1::PostOutcomeResponse* response,
                           const std::vector<std::uint32_t>& moved_with_target = {},
                           const std::vector<std::uint32_t>& same_object = {});
  // The outcome as the cloud after the push: the server's change detector labels it.
  // Either PostOutcome fails as IsFrameGone when the server has lost the frame.
  grpc::Status PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                           std::uint32_t supervoxel_id, const v1::Cloud& after_cloud,
                           const std::string& request_id, v1::PostOutcomeResponse* response);
  // `request`'s session id (and an empty request id) are filled in here.
  grpc::Status ClassifyFeatures(const SessionHandle& session, v1::ClassifyFeaturesRequest request,
                                v1::ClassifyFeaturesResponse* response);
  grpc::Status AddSamples(const SessionHandle& session, v1::AddSamplesRequest request,
                          v1::AddSamplesResponse* response);
  grpc::Status ExportSession(const SessionHandle& session, v1::ExportSessionResponse* response);
  // A new session from exported state; `session` receives its id and token.
  grpc::Status ImportSession(const v1::SessionState& state, SessionHandle* session,
                             v1::ImportSessionResponse* response = nullptr);

  // grpc.health.v1.Health/Check of `service`: "" is the whole server, which
  // relmap-server answers for, as for "relmap.v1.RelevanceService" (other names are
  // NOT_FOUND). What load balancers and probes
  // ask; a server that drains before it stops answers NOT_SERVING. Retried like any
  // idempotent call, within the deadline.
  grpc::Status CheckHealth(const std::string& service,
                           grpc::health::v1::HealthCheckResponse* response);

  // The admin key sent with CreateSession, ListSessions, DeleteSession and
  // ImportSession, for servers started with one.
  void set_admin_key(std::string key) { admin_key_ = std::move(key); }
  const ClientOptions& options() const { return options_; }
  // Attempts beyond the first, over the client's life.
  std::uint64_t retries() const { return retries_.load(); }

  v1::RelevanceService::Stub& stub() { return *stub_; }

 private:
  using Metadata = std::vector<std::pair<std::string, std::string>>;
  template <typename Request, typename Response>
  using Rpc = grpc::Status (v1::RelevanceService::Stub::*)(grpc::ClientContext*, const Request&,
                                                           Response*);

  // One logical call: attempts of `attempt` (one RPC on the context it is given,
  // which carries the deadline and `metadata`) until success, a final status, the
  // attempt limit or the deadline. Every call of this client goes through here.
  grpc::Status Retrying(const std::function<grpc::Status(grpc::ClientContext&)>& attempt,
                        Idempotence idempotence, const Metadata& metadata);
  // Retrying over one method of the stub.
  template <typename Request, typename Response>
  grpc::Status Invoke(Rpc<Request, Response> rpc, const Request& request, Response* response,
                      Idempotence idempotence, const Metadata& metadata);

  // CreateSession and ImportSession: an admin call that yields a new session, whose id
  // and token go to `session` (and the whole answer to `response` if not null).
  template <typename Request, typename Response>
  grpc::Status StartSession(Rpc<Request, Response> rpc, const Request& request,
                            SessionHandle* session, Response* response);

  // The metadata of a call on `session`: its bearer token, and its id as
  // x-relmap-session for load balancers that route by session.
  static Metadata SessionMetadata(const SessionHandle& session);
  Metadata AdminMetadata() const;
  // A PostOutcomeRequest without its outcome.
  static v1::PostOutcomeRequest OutcomeRequest(const SessionHandle& session, std::uint64_t frame_id,
                                               std::uint32_t supervoxel_id,
                                               const std::string& request_id);

  ClientOptions options_;
  std::shared_ptr<grpc::Channel> channel_;
  std::unique_ptr<v1::RelevanceService::Stub> stub_;
  std::string admin_key_;
  std::atomic<std::uint64_t> retries_{0};
};

// Whether a PostOutcome failed because the server no longer has the frame it names:
// evicted from the session's cache, or lost with the server that computed it (a
// restart, or the session taken over by another server: frames live in the memory
// of the server that made them). Nothing was learned; the caller goes on from new
// maps. The server's reason FRAME_GONE says so (error_reason.h), not its message.
bool IsFrameGone(const grpc::Status& status);

// A cloud message carrying the bytes of a PCD file.
v1::Cloud PcdCloud(std::string pcd_bytes);

// 128 random bits as 32 hex digits: a request id no other client will pick.
std::string RandomRequestId();

}  // namespace relmap::client
