// The harness of service_harness.h.
#include "fuzz/service_harness.h"

#include <google/protobuf/stubs/logging.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/test/server_context_test_spouse.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "relmap/v1/relevance_service.pb.h"
#include "service/relevance_service.h"
#include "session/registry/session_registry.h"

namespace relmap::fuzz {
namespace {

// Small enough that a mapped cloud costs milliseconds: 32 x 24 points, a handful of
// feature vectors per request, sessions as in a test.
constexpr std::size_t kMaxSessions = 4;
constexpr long long kMaxPoints = 32LL * 24;
constexpr std::size_t kMaxFeaturesPerRequest = 16;

service::ServiceLimits FuzzLimits() {
  service::ServiceLimits limits;
  limits.decode.max_points = kMaxPoints;
  limits.decode.max_bytes = 64 << 10;
  limits.max_features_per_request = kMaxFeaturesPerRequest;
  limits.concurrent_frames = 1;
  limits.queued_frames = 0;
  return limits;
}

// RELMAP_FUZZ_VERBOSE=1: each call's status on stderr, to see what a seed reaches.
bool Verbose() {
  static const bool verbose = std::getenv("RELMAP_FUZZ_VERBOSE") != nullptr;
  return verbose;
}

// The service of one input, and its session if the setup made one.
class Harness {
 public:
  Harness() : registry_(kMaxSessions), service_(registry_, FuzzLimits()) {}

  // The session and the frame of the setup, if it makes them.
  void Prepare(const CallSetup& setup) {
    if (!setup.create_session) return;
    CreateSession(setup.create_request);
    if (session_id_.empty() || setup.first_frame.empty()) return;
    CallSetup own;
    own.use_session_id = true;
    own.send_token = true;
    Call<v1::ComputeMapsRequest, v1::ComputeMapsResponse>(
        setup.first_frame, own, &service::RelevanceService::ComputeMaps,
        [this](const v1::ComputeMapsResponse& maps) { frame_id_ = maps.frame_id(); });
  }

  // Parses `bytes` as Request, applies the setup and calls `handler`; an OK
  // response goes to `on_ok`.
  template <typename Request, typename Response, typename Handler, typename OnOk>
  bool Call(std::string_view bytes, const CallSetup& setup, Handler handler, OnOk on_ok) {
    Request request;
    if (!request.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()))) return false;
    if constexpr (requires { request.set_session_id(std::string()); }) {
      if (setup.use_session_id && !session_id_.empty()) request.set_session_id(session_id_);
    }
    if constexpr (requires { request.set_frame_id(0); }) {
      if (setup.use_session_id && frame_id_) request.set_frame_id(*frame_id_);
    }
    grpc::ServerContext context;
    grpc::testing::ServerContextTestSpouse metadata(&context);
    if (setup.send_token && !token_.empty()) {
      metadata.AddClientMetadata("authorization", "Bearer " + token_);
    }
    Response response;
    const grpc::Status status = (service_.*handler)(&context, &request, &response);
    if (Verbose()) {
      std::fprintf(stderr, "%s: %d %s\n", Request::descriptor()->name().c_str(),
                   static_cast<int>(status.error_code()), status.error_message().c_str());
    }
    // A handler answers with a status; an OK CreateSession or ImportSession names
    // the session it made.
    if constexpr (requires { response.session_token(); }) {
      if (status.ok() && response.session_id().empty()) std::abort();
    }
    if (status.ok()) on_ok(response);
    return true;
  }

  template <typename Request, typename Response, typename Handler>
  bool Call(std::string_view bytes, const CallSetup& setup, Handler handler) {
    return Call<Request, Response>(bytes, setup, handler, [](const Response&) {});
  }

 private:
  void CreateSession(std::string_view serialized) {
    v1::CreateSessionRequest request;
    if (!request.ParseFromArray(serialized.data(), static_cast<int>(serialized.size()))) return;
    grpc::ServerContext context;
    v1::CreateSessionResponse response;
    if (!service_.CreateSession(&context, &request, &response).ok()) return;
    session_id_ = response.session_id();
    token_ = response.session_token();
  }

  session::SessionRegistry registry_;
  service::RelevanceService service_;
  std::string session_id_;
  std::string token_;
  std::optional<std::uint64_t> frame_id_;
};

}  // namespace

bool CallOnce(Rpc rpc, std::string_view request, const CallSetup& setup) {
  static const bool quiet = [] {
    spdlog::set_level(spdlog::level::off);  // the handlers log every call
    // and protobuf every string field of a fuzzed request that is not UTF-8.
    google::protobuf::SetLogHandler(nullptr);
    return true;
  }();
  (void)quiet;
  Harness harness;
  harness.Prepare(setup);
  using S = service::RelevanceService;
  switch (rpc) {
    case Rpc::kCreateSession:
      return harness.Call<v1::CreateSessionRequest, v1::CreateSessionResponse>(request, setup,
                                                                               &S::CreateSession);
    case Rpc::kGetSession:
      return harness.Call<v1::GetSessionRequest, v1::GetSessionResponse>(request, setup,
                                                                         &S::GetSession);
    case Rpc::kListSessions:
      return harness.Call<v1::ListSessionsRequest, v1::ListSessionsResponse>(request, setup,
                                                                             &S::ListSessions);
    case Rpc::kDeleteSession:
      return harness.Call<v1::DeleteSessionRequest, v1::DeleteSessionResponse>(request, setup,
                                                                               &S::DeleteSession);
    case Rpc::kComputeMaps:
      return harness.Call<v1::ComputeMapsRequest, v1::ComputeMapsResponse>(request, setup,
                                                                           &S::ComputeMaps);
    case Rpc::kPostOutcome:
      return harness.Call<v1::PostOutcomeRequest, v1::PostOutcomeResponse>(request, setup,
                                                                           &S::PostOutcome);
    case Rpc::kClassifyFeatures:
      return harness.Call<v1::ClassifyFeaturesRequest, v1::ClassifyFeaturesResponse>(
          request, setup, &S::ClassifyFeatures);
    case Rpc::kAddSamples:
      return harness.Call<v1::AddSamplesRequest, v1::AddSamplesResponse>(request, setup,
                                                                         &S::AddSamples);
    case Rpc::kExportSession:
      return harness.Call<v1::ExportSessionRequest, v1::ExportSessionResponse>(request, setup,
                                                                               &S::ExportSession);
    case Rpc::kImportSession:
      return harness.Call<v1::ImportSessionRequest, v1::ImportSessionResponse>(request, setup,
                                                                               &S::ImportSession);
  }
  return false;
}

}  // namespace relmap::fuzz
