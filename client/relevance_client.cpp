// Thin wrappers over the generated stub.
#include "relevance_client.h"

namespace relmap::client {

RelevanceClient::RelevanceClient(const std::string& address, int max_message_bytes) {
  grpc::ChannelArguments arguments;
  arguments.SetMaxSendMessageSize(max_message_bytes);
  arguments.SetMaxReceiveMessageSize(max_message_bytes);
  stub_ = v1::RelevanceService::NewStub(
      grpc::CreateCustomChannel(address, grpc::InsecureChannelCredentials(), arguments));
}

void RelevanceClient::Authorise(grpc::ClientContext& context, const SessionHandle& session) {
  context.AddMetadata("authorization", "Bearer " + session.token);
  context.AddMetadata("x-relmap-session", session.id);
}

void RelevanceClient::AddAdminKey(grpc::ClientContext& context) const {
  if (!admin_key_.empty()) context.AddMetadata("x-relmap-admin-key", admin_key_);
}

grpc::Status RelevanceClient::CreateSession(const v1::SessionConfig& config, SessionHandle* session,
                                            v1::CreateSessionResponse* response) {
  grpc::ClientContext context;
  AddAdminKey(context);
  v1::CreateSessionRequest request;
  *request.mutable_config() = config;
  v1::CreateSessionResponse local;
  v1::CreateSessionResponse* out = response != nullptr ? response : &local;
  const grpc::Status status = stub_->CreateSession(&context, request, out);
  if (status.ok()) *session = {out->session_id(), out->session_token()};
  return status;
}

grpc::Status RelevanceClient::GetSession(const SessionHandle& session,
                                         v1::GetSessionResponse* response) {
  grpc::ClientContext context;
  Authorise(context, session);
  v1::GetSessionRequest request;
  request.set_session_id(session.id);
  return stub_->GetSession(&context, request, response);
}

grpc::Status RelevanceClient::ListSessions(v1::ListSessionsResponse* response) {
  grpc::ClientContext context;
  AddAdminKey(context);
  return stub_->ListSessions(&context, v1::ListSessionsRequest{}, response);
}

grpc::Status RelevanceClient::DeleteSession(const SessionHandle& session) {
  grpc::ClientContext context;
  Authorise(context, session);
  AddAdminKey(context);
  v1::DeleteSessionRequest request;
  request.set_session_id(session.id);
  v1::DeleteSessionResponse response;
  return stub_->DeleteSession(&context, request, &response);
}

grpc::Status RelevanceClient::ComputeMaps(const SessionHandle& session, const v1::Cloud& cloud,
                                          v1::ComputeMapsResponse* response) {
  grpc::ClientContext context;
  Authorise(context, session);
  v1::ComputeMapsRequest request;
  request.set_session_id(session.id);
  *request.mutable_cloud() = cloud;
  return stub_->ComputeMaps(&context, request, response);
}

grpc::Status RelevanceClient::PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                                          std::uint32_t supervoxel_id, v1::Label label,
                                          const std::string& request_id,
                                          v1::PostOutcomeResponse* response) {
  v1::PostOutcomeRequest request = OutcomeRequest(session, frame_id, supervoxel_id, request_id);
  request.set_label(label);
  return SendOutcome(session, request, response);
}

grpc::Status RelevanceClient::PostOutcome(const SessionHandle& session, std::uint64_t frame_id,
                                          std::uint32_t supervoxel_id, const v1::Cloud& after_cloud,
                                          const std::string& request_id,
                                          v1::PostOutcomeResponse* response) {
  v1::PostOutcomeRequest request = OutcomeRequest(session, frame_id, supervoxel_id, request_id);
  *request.mutable_after_cloud() = after_cloud;
  return SendOutcome(session, request, response);
}

v1::PostOutcomeRequest RelevanceClient::OutcomeRequest(const SessionHandle& session,
                                                       std::uint64_t frame_id,
                                                       std::uint32_t supervoxel_id,
                                                       const std::string& request_id) {
  v1::PostOutcomeRequest request;
  request.set_session_id(session.id);
  request.set_frame_id(frame_id);
  request.set_supervoxel_id(supervoxel_id);
  request.set_request_id(request_id);
  return request;
}

grpc::Status RelevanceClient::SendOutcome(const SessionHandle& session,
                                          const v1::PostOutcomeRequest& request,
                                          v1::PostOutcomeResponse* response) {
  grpc::ClientContext context;
  Authorise(context, session);
  return stub_->PostOutcome(&context, request, response);
}

v1::Cloud PcdCloud(std::string pcd_bytes) {
  v1::Cloud cloud;
  cloud.set_pcd(std::move(pcd_bytes));
  return cloud;
}

}  // namespace relmap::client
