// Every call that names a session carries its id as x-relmap-session metadata, for
// the load balancers that keep a session on one server (deploy/); the calls that
// name none carry no such header — against an in-process server that records them.
#include <gtest/gtest.h>

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "client/in_process_server.h"
#include "relevance_client.h"

namespace relmap::client {
namespace {

// Answers every call with OK and records, per method, the x-relmap-session values
// the call arrived with.
class RecordingService final : public v1::RelevanceService::Service {
 public:
  grpc::Status CreateSession(grpc::ServerContext* context, const v1::CreateSessionRequest*,
                             v1::CreateSessionResponse* response) override {
    response->set_session_id("created");
    return Record("CreateSession", context);
  }
  grpc::Status GetSession(grpc::ServerContext* context, const v1::GetSessionRequest*,
                          v1::GetSessionResponse*) override {
    return Record("GetSession", context);
  }
  grpc::Status ListSessions(grpc::ServerContext* context, const v1::ListSessionsRequest*,
                            v1::ListSessionsResponse*) override {
    return Record("ListSessions", context);
  }
  grpc::Status DeleteSession(grpc::ServerContext* context, const v1::DeleteSessionRequest*,
                             v1::DeleteSessionResponse*) override {
    return Record("DeleteSession", context);
  }
  grpc::Status ComputeMaps(grpc::ServerContext* context, const v1::ComputeMapsRequest*,
                           v1::ComputeMapsResponse*) override {
    return Record("ComputeMaps", context);
  }
  grpc::Status PostOutcome(grpc::ServerContext* context, const v1::PostOutcomeRequest* request,
                           v1::PostOutcomeResponse*) override {
    return Record(request->has_after_cloud() ? "PostOutcome(after cloud)" : "PostOutcome(label)",
                  context);
  }
  grpc::Status ClassifyFeatures(grpc::ServerContext* context, const v1::ClassifyFeaturesRequest*,
                                v1::ClassifyFeaturesResponse*) override {
    return Record("ClassifyFeatures", context);
  }
  grpc::Status AddSamples(grpc::ServerContext* context, const v1::AddSamplesRequest*,
                          v1::AddSamplesResponse*) override {
    return Record("AddSamples", context);
  }
  grpc::Status ExportSession(grpc::ServerContext* context, const v1::ExportSessionRequest*,
                             v1::ExportSessionResponse*) override {
    return Record("ExportSession", context);
  }
  grpc::Status ImportSession(grpc::ServerContext* context, const v1::ImportSessionRequest*,
                             v1::ImportSessionResponse* response) override {
    response->set_session_id("imported");
    return Record("ImportSession", context);
  }

  // Per method: the x-relmap-session values of its calls, one list per call.
  std::map<std::string, std::vector<std::vector<std::string>>> headers() const {
    std::lock_guard lock(mutex_);
    return headers_;
  }

 private:
  grpc::Status Record(const std::string& method, grpc::ServerContext* context) {
    std::vector<std::string> values;
    const auto [first, last] = context->client_metadata().equal_range("x-relmap-session");
    for (auto it = first; it != last; ++it)
      values.emplace_back(it->second.data(), it->second.size());
    std::lock_guard lock(mutex_);
    headers_[method].push_back(std::move(values));
    return grpc::Status::OK;
  }

  mutable std::mutex mutex_;
  std::map<std::string, std::vector<std::vector<std::string>>> headers_;
};

class SessionHeader : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string address;
    server_ = StartInProcessServer(&service_, &address);
    ASSERT_NE(server_, nullptr);
    client_ = std::make_unique<RelevanceClient>(address);
  }
  void TearDown() override { server_->Shutdown(); }

  // The x-relmap-session values of the one call `method` received.
  std::vector<std::string> HeaderOf(const std::string& method) const {
    const auto headers = service_.headers();
    const auto it = headers.find(method);
    if (it == headers.end() || it->second.size() != 1) {
      ADD_FAILURE() << method << ": expected one call";
      return {};
    }
    return it->second.front();
  }

  const SessionHandle session_{"3f2a9c1e", "token"};
  RecordingService service_;
  std::unique_ptr<grpc::Server> server_;
  std::unique_ptr<RelevanceClient> client_;
};

TEST_F(SessionHeader, EveryCallOnASessionCarriesItsIdOnce) {
  v1::GetSessionResponse session;
  ASSERT_TRUE(client_->GetSession(session_, &session).ok());
  v1::ComputeMapsResponse maps;
  ASSERT_TRUE(client_->ComputeMaps(session_, v1::Cloud{}, &maps).ok());
  v1::PostOutcomeResponse outcome;
  ASSERT_TRUE(client_->PostOutcome(session_, 1, 2, v1::LABEL_MOVEABLE, "", &outcome).ok());
  ASSERT_TRUE(client_->PostOutcome(session_, 1, 2, PcdCloud("pcd"), "", &outcome).ok());
  v1::ClassifyFeaturesResponse classified;
  ASSERT_TRUE(client_->ClassifyFeatures(session_, {}, &classified).ok());
  v1::AddSamplesResponse added;
  ASSERT_TRUE(client_->AddSamples(session_, {}, &added).ok());
  v1::ExportSessionResponse exported;
  ASSERT_TRUE(client_->ExportSession(session_, &exported).ok());
  client_->set_admin_key("admin");  // DeleteSession sends both kinds of metadata
  ASSERT_TRUE(client_->DeleteSession(session_).ok());

  for (const char* method :
       {"GetSession", "ComputeMaps", "PostOutcome(label)", "PostOutcome(after cloud)",
        "ClassifyFeatures", "AddSamples", "ExportSession", "DeleteSession"}) {
    EXPECT_EQ(HeaderOf(method), std::vector<std::string>{session_.id}) << method;
  }
}

TEST_F(SessionHeader, CallsThatNameNoSessionCarryNone) {
  SessionHandle created;
  ASSERT_TRUE(client_->CreateSession({}, &created).ok());
  v1::ListSessionsResponse sessions;
  ASSERT_TRUE(client_->ListSessions(&sessions).ok());
  SessionHandle imported;
  ASSERT_TRUE(client_->ImportSession({}, &imported).ok());

  for (const char* method : {"CreateSession", "ListSessions", "ImportSession"}) {
    EXPECT_TRUE(HeaderOf(method).empty()) << method;
  }
}

}  // namespace
}  // namespace relmap::client
