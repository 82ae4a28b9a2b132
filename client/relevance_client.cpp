// Each RPC is one line of request building over Retrying (through Invoke for the
// relevance service's own methods), which owns the deadline, the metadata and the
// retries.
#include "relevance_client.h"

#include <grpcpp/generic/generic_stub.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <random>
#include <thread>

namespace relmap::client {
namespace {

std::shared_ptr<grpc::Channel> MakeChannel(const ClientOptions& options) {
  grpc::ChannelArguments arguments;
  arguments.SetMaxSendMessageSize(options.max_message_bytes);
  arguments.SetMaxReceiveMessageSize(options.max_message_bytes);
  if (options.tls_root_certificates.empty()) {
    return grpc::CreateCustomChannel(options.address, grpc::InsecureChannelCredentials(),
                                     arguments);
  }
  grpc::SslCredentialsOptions tls;
  tls.pem_root_certs = options.tls_root_certificates;
  return grpc::CreateCustomChannel(options.address, grpc::SslCredentials(tls), arguments);
}

// Per thread, so that the client can be shared without a lock.
std::mt19937_64& ThreadRandom() {
  thread_local std::mt19937_64 random = [] {
    std::random_device device;
    std::seed_seq seed{device(), device(), device(), device()};
    return std::mt19937_64(seed);
  }();
  return random;
}

const std::string& OrRandom(const std::string& request_id, std::string& generated) {
  if (!request_id.empty()) return request_id;
  generated = RandomRequestId();
  return generated;
}

ClientOptions PlaintextOptions(const std::string& address, int max_message_bytes) {
  ClientOptions options;
  options.address = address;
  options.max_message_bytes = max_message_bytes;
  return options;
}

}  // namespace

RelevanceClient::RelevanceClient(ClientOptions options)
    : options_(std::move(options)),
      channel_(MakeChannel(options_)),
      stub_(v1::RelevanceService::NewStub(channel_)) {}

RelevanceClient::RelevanceClient(const std::string& address, int max_message_bytes)
    : RelevanceClient(PlaintextOptions(address, max_message_bytes)) {}

grpc::Status RelevanceClient::Retrying(
    const std::function<grpc::Status(grpc::ClientContext&)>& attempt, Idempotence idempotence,
    const Metadata& metadata) {
  const auto deadline = std::chrono::system_clock::now() + options_.deadline;
  int attempts = 0;  // pushbacks excepted: those are repeated until the deadline
  for (int call = 1;; ++call) {
    grpc::ClientContext context;
    context.set_deadline(deadline);
    for (const auto& [key, value] : metadata) context.AddMetadata(key, value);
    grpc::Status status = attempt(context);
    const std::optional<std::chrono::milliseconds> pushback = PushbackOf(context);
    if (status.ok() || !IsRetryable(status, idempotence, pushback.has_value())) return status;
    if (!pushback && ++attempts >= options_.retry.max_attempts) return status;
    const std::chrono::milliseconds wait =
        std::max(pushback.value_or(std::chrono::milliseconds(0)),
                 BackoffBefore(call + 1, options_.retry,
                               std::uniform_real_distribution<double>(0.0, 1.0)(ThreadRandom())));
    if (std::chrono::system_clock::now() + wait >= deadline) return status;
    std::this_thread::sleep_for(wait);
    ++retries_;
  }
}

template <typename Request, typename Response>
grpc::Status RelevanceClient::Invoke(Rpc<Request, Response> rpc, const Request& request,
                                     Response* response, Idempotence idempotence,
                                     const Metadata& metadata) {
  return Retrying(
      [&](grpc::ClientContext& context) { return ((*stub_).*rpc)(&context, request, response); },
      idempotence, metadata);
}

template <typename Request, typename Response>
grpc::Status RelevanceClient::StartSession(Rpc<Request, Response> rpc, const Request& request,
                                           SessionHandle* session, Response* response) {
  Response local;
  Response* out = response != nullptr ? response : &local;
  grpc::Status status = Invoke(rpc, request, out, Idempotence::kNotIdempotent, AdminMetadata());
  if (status.ok()) *session = {out->session_id(), out->session_token()};
  return status;
}

RelevanceClient::Metadata RelevanceClient::SessionMetadata(const SessionHandle& session) {
  return {{"authorization", "Bearer " + session.token}, {"x-relmap-session", session.id}};
}

RelevanceClient::Metadata RelevanceClient::AdminMetadata() const {
  if (admin_key_.empty()) return {};
  return {{"x-relmap-admin-key", admin_key_}};
}

grpc::Status RelevanceClient::CreateSession(const v1::SessionConfig& config, SessionHandle* session,
                                            v1::CreateSessionResponse* response) {
  v1::CreateSessionRequest request;
  *request.mutable_config() = config;
  return StartSession(&v1::RelevanceService::Stub::CreateSession, request, session, response);
}

grpc::Status RelevanceClient::GetSession(const SessionHandle& session,
                                         v1::GetSessionResponse* response) {
  v1::GetSessionRequest request;
  request.set_session_id(session.id);
  return Invoke(&v1::RelevanceService::Stub::GetSession, request, response,
                Idempotence::kIdempotent, SessionMetadata(session));
}

grpc::Status RelevanceClient::ListSessions(v1::ListSessionsResponse* response) {
  response->Clear();
  v1::ListSessionsRequest request;
  do {
    v1::ListSessionsResponse page;
    if (grpc::Status status = ListSessionsPage(request, &page); !status.ok()) return status;
    for (v1::GetSessionResponse& session : *page.mutable_sessions()) {
      *response->add_sessions() = std::move(session);
    }
    request.set_page_token(page.next_page_token());
  } while (!request.page_token().empty());
  return grpc::Status::OK;
}

grpc::Status RelevanceClient::ListSessionsPage(const v1::ListSessionsRequest& request,
                                               v1::ListSessionsResponse* response) {
  return Invoke(&v1::RelevanceService::Stub::ListSessions, request, response,
                Idempotence::kIdempotent, AdminMetadata());
}

grpc::Status RelevanceClient::DeleteSession(const SessionHandle& session) {
  v1::DeleteSessionRequest request;
  request.set_session_id(session.id);
  v1::DeleteSessionResponse response;
  Metadata metadata = SessionMetadata(session);
  for (auto& entry : AdminMetadata()) metadata.push_back(std::move(entry));
  // Not idempotent in its answer: a repeat after a lost reply would say NOT_FOUND.
  return Invoke(&v1::RelevanceService::Stub::DeleteSession, request, &response,
                Idempotence::kNotIdempotent, metadata);
}

grpc::Status RelevanceClient::ComputeMaps(const SessionHandle& session, const v1::Cloud& cloud,
                                          v1::ComputeMapsResponse* response,
                                          PointLabels point_labels, MapsRepeat repeat,
                                          SupervoxelFeatures features) {
  v1::ComputeMapsRequest request;
  request.set_session_id(session.id);
  *request.mutable_cloud() = cloud;
  request.set_omit_point_labels(point_labels == PointLabels::kOmit);
  request.set_include_features(features == SupervoxelFeatures::kInclude);
  // A repeat would draw another target and cache another frame: only when asked.
  return Invoke(&v1::RelevanceService::Stub::ComputeMaps, request, response,
                repeat == MapsRepeat::kAfterBrokenConnection ? Idempotence::kIdempotent
                                                             : Idempotence::kNotIdempotent,
                SessionMetadata(session));
}

grpc::Status RelevanceClient::PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                                          std::uint32_t supervoxel_id, v1::Label label,
                                          const std::string& request_id,
                                          v1::PostOutcomeResponse* response,
                                          const std::vector<std::uint32_t>& moved_with_target,
                                          const std::vector<std::uint32_t>& same_object) {
  v1::PostOutcomeRequest request = OutcomeRequest(session, frame_id, supervoxel_id, request_id);
  request.set_label(label);
  request.mutable_moved_supervoxels()->Add(moved_with_target.begin(), moved_with_target.end());
  request.mutable_object_supervoxels()->Add(same_object.begin(), same_object.end());
  return Invoke(&v1::RelevanceService::Stub::PostOutcome, request, response,
                Idempotence::kIdempotent, SessionMetadata(session));
}

grpc::Status RelevanceClient::PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                                          std::uint32_t supervoxel_id, const v1::Cloud& after_cloud,
                                          const std::string& request_id,
                                          v1::PostOutcomeResponse* response) {
  v1::PostOutcomeRequest request = OutcomeRequest(session, frame_id, supervoxel_id, request_id);
  *request.mutable_after_cloud() = after_cloud;
  return Invoke(&v1::RelevanceService::Stub::PostOutcome, request, response,
                Idempotence::kIdempotent, SessionMetadata(session));
}

v1::PostOutcomeRequest RelevanceClient::OutcomeRequest(const SessionHandle& session,
                                                       std::uint64_t frame_id,
                                                       std::uint32_t supervoxel_id,
                                                       const std::string& request_id) {
  v1::PostOutcomeRequest request;
  request.set_session_id(session.id);
  request.set_frame_id(frame_id);
  request.set_supervoxel_id(supervoxel_id);
  std::string generated;
  request.set_request_id(OrRandom(request_id, generated));
  return request;
}

grpc::Status RelevanceClient::ClassifyFeatures(const SessionHandle& session,
                                               v1::ClassifyFeaturesRequest request,
                                               v1::ClassifyFeaturesResponse* response) {
  request.set_session_id(session.id);
  return Invoke(&v1::RelevanceService::Stub::ClassifyFeatures, request, response,
                Idempotence::kIdempotent, SessionMetadata(session));
}

grpc::Status RelevanceClient::AddSamples(const SessionHandle& session,
                                         v1::AddSamplesRequest request,
                                         v1::AddSamplesResponse* response) {
  request.set_session_id(session.id);
  std::string generated;
  request.set_request_id(OrRandom(request.request_id(), generated));
  return Invoke(&v1::RelevanceService::Stub::AddSamples, request, response,
                Idempotence::kIdempotent, SessionMetadata(session));
}

grpc::Status RelevanceClient::ExportSession(const SessionHandle& session,
                                            v1::ExportSessionResponse* response) {
  v1::ExportSessionRequest request;
  request.set_session_id(session.id);
  return Invoke(&v1::RelevanceService::Stub::ExportSession, request, response,
                Idempotence::kIdempotent, SessionMetadata(session));
}

grpc::Status RelevanceClient::ImportSession(const v1::SessionState& state, SessionHandle* session,
                                            v1::ImportSessionResponse* response) {
  v1::ImportSessionRequest request;
  *request.mutable_state() = state;
  return StartSession(&v1::RelevanceService::Stub::ImportSession, request, session, response);
}

grpc::Status RelevanceClient::CheckHealth(const std::string& service,
                                          grpc::health::v1::HealthCheckResponse* response) {
  using grpc::health::v1::HealthCheckRequest;
  using grpc::health::v1::HealthCheckResponse;
  // The health service's messages are linked in, its stub is not: a generic stub over
  // the same channel, waited on here.
  grpc::TemplatedGenericStub<HealthCheckRequest, HealthCheckResponse> health(channel_);
  HealthCheckRequest request;
  request.set_service(service);
  return Retrying(
      [&](grpc::ClientContext& context) {
        std::promise<grpc::Status> done;
        health.UnaryCall(&context, "/grpc.health.v1.Health/Check", grpc::StubOptions(), &request,
                         response, [&done](const grpc::Status& status) { done.set_value(status); });
        return done.get_future().get();
      },
      Idempotence::kIdempotent, {});
}

bool IsFrameGone(const grpc::Status& status) { return ReasonOf(status) == v1::FRAME_GONE; }

v1::Cloud PcdCloud(std::string pcd_bytes) {
  v1::Cloud cloud;
  cloud.set_pcd(std::move(pcd_bytes));
  return cloud;
}

std::string RandomRequestId() {
  std::mt19937_64& random = ThreadRandom();
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(random()),
                static_cast<unsigned long long>(random()));
  return hex;
}

}  // namespace relmap::client
