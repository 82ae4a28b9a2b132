// Figures for stored sessions against a running relmap-server (docs/reliability.md,
// "Stored sessions"): fill it with sessions of random 48-d samples, then, after a
// restart on the same store, time an admin ListSessions over all of them and the
// first call of one session (its restore; the server logs "restored session=...
// in T ms" for the part inside the server).
//   stored_sessions_probe fill ADDRESS SESSIONS SAMPLES [SEED] > sessions.txt
//   stored_sessions_probe add ADDRESS ID TOKEN SAMPLES [SEED]
//   stored_sessions_probe list ADDRESS
//   stored_sessions_probe first-call ADDRESS ID TOKEN
// `add` appends samples to one session (to leave samples after its latest snapshot, run
// the server with --snapshot-every 0 --snapshot-after-learning-ms 0 meanwhile).
// Samples: uniform [0,1)^48 with fair random labels (learning_cost_probe's random48),
// sent as AddSamples batches of 250; sessions.txt gets "ID TOKEN" per session.
// Wall-clock times of the calls as the client sees them.
#include <grpcpp/grpcpp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <string_view>

#include "common/command_line.h"
#include "common/random.h"
#include "relmap/v1/relevance_service.grpc.pb.h"

namespace relmap {
namespace {

constexpr std::string_view kProgram = "stored_sessions_probe";
constexpr int kDimension = 48;
constexpr int kBatch = 250;

[[noreturn]] void Fail(const std::string& message) { tools::ExitWithError(kProgram, message); }

void Check(const grpc::Status& status, const char* call) {
  if (!status.ok()) Fail(std::string(call) + ": " + status.error_message());
}

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// AddSamples of `count` random samples to a session, in batches of kBatch.
void AddRandomSamples(v1::RelevanceService::Stub& stub, const std::string& id,
                      const std::string& token, long count, const std::string& request_prefix,
                      Random& random) {
  for (long first = 0; first < count; first += kBatch) {
    v1::AddSamplesRequest add;
    add.set_session_id(id);
    add.set_request_id(request_prefix + std::to_string(first));
    for (long i = first; i < std::min(count, first + kBatch); ++i) {
      v1::LabelledFeature* sample = add.add_samples();
      for (int d = 0; d < kDimension; ++d)
        sample->mutable_feature()->add_values(random.UniformUnit());
      sample->set_label(random.UniformIndex(2) == 1 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
    }
    grpc::ClientContext context;
    context.AddMetadata("authorization", "Bearer " + token);
    v1::AddSamplesResponse added;
    Check(stub.AddSamples(&context, add, &added), "AddSamples");
  }
}

void Fill(v1::RelevanceService::Stub& stub, long sessions, long samples, std::uint64_t seed) {
  Random random(seed);
  const auto start = std::chrono::steady_clock::now();
  for (long s = 0; s < sessions; ++s) {
    grpc::ClientContext create_context;
    v1::CreateSessionRequest create;
    create.mutable_config()->set_seed(seed + static_cast<std::uint64_t>(s));
    v1::CreateSessionResponse created;
    Check(stub.CreateSession(&create_context, create, &created), "CreateSession");
    AddRandomSamples(stub, created.session_id(), created.session_token(), samples, "fill-", random);
    std::printf("%s %s\n", created.session_id().c_str(), created.session_token().c_str());
    std::fflush(stdout);
    std::fprintf(stderr, "%ld/%ld sessions of %ld samples, %.0f s\n", s + 1, sessions, samples,
                 MillisecondsSince(start) / 1000.0);
  }
}

void List(v1::RelevanceService::Stub& stub) {
  const auto start = std::chrono::steady_clock::now();
  long listed = 0;
  long samples = 0;
  std::string token;
  do {
    grpc::ClientContext context;
    v1::ListSessionsRequest request;
    request.set_page_size(1000);
    request.set_page_token(token);
    v1::ListSessionsResponse response;
    Check(stub.ListSessions(&context, request, &response), "ListSessions");
    for (const v1::GetSessionResponse& session : response.sessions()) {
      samples += static_cast<long>(session.stats().moveable_samples() +
                                   session.stats().non_moveable_samples());
    }
    listed += response.sessions_size();
    token = response.next_page_token();
  } while (!token.empty());
  std::printf("ListSessions (pages of 1000): %ld sessions, %ld samples, %.1f ms\n", listed, samples,
              MillisecondsSince(start));
}

void FirstCall(v1::RelevanceService::Stub& stub, const std::string& id, const std::string& token) {
  grpc::ClientContext context;
  context.AddMetadata("authorization", "Bearer " + token);
  v1::GetSessionRequest request;
  request.set_session_id(id);
  v1::GetSessionResponse response;
  const auto start = std::chrono::steady_clock::now();
  Check(stub.GetSession(&context, request, &response), "GetSession");
  std::printf("GetSession %s: %.1f ms (%lu samples, components %u + %u)\n", id.c_str(),
              MillisecondsSince(start),
              static_cast<unsigned long>(response.stats().moveable_samples() +
                                         response.stats().non_moveable_samples()),
              response.stats().non_moveable_components(), response.stats().moveable_components());
}

}  // namespace
}  // namespace relmap

int main(int argc, char** argv) {
  using namespace relmap;
  constexpr const char* kUsage =
      "usage: fill ADDRESS SESSIONS SAMPLES [SEED] | add ADDRESS ID TOKEN SAMPLES [SEED] |"
      " list ADDRESS | first-call ADDRESS ID TOKEN";
  if (argc < 3) Fail(kUsage);
  const std::string command = argv[1];
  grpc::ChannelArguments arguments;
  arguments.SetMaxReceiveMessageSize(64 << 20);
  auto stub = v1::RelevanceService::NewStub(
      grpc::CreateCustomChannel(argv[2], grpc::InsecureChannelCredentials(), arguments));
  if (command == "fill" && (argc == 5 || argc == 6)) {
    const auto sessions =
        static_cast<long>(tools::ParseNumberOrExit(kProgram, "SESSIONS", argv[3]));
    const auto samples = static_cast<long>(tools::ParseNumberOrExit(kProgram, "SAMPLES", argv[4]));
    const auto seed =
        argc == 6 ? static_cast<std::uint64_t>(tools::ParseNumberOrExit(kProgram, "SEED", argv[5]))
                  : 1;
    Fill(*stub, sessions, samples, seed);
  } else if (command == "add" && (argc == 6 || argc == 7)) {
    const auto samples = static_cast<long>(tools::ParseNumberOrExit(kProgram, "SAMPLES", argv[5]));
    Random random(
        argc == 7 ? static_cast<std::uint64_t>(tools::ParseNumberOrExit(kProgram, "SEED", argv[6]))
                  : 2);
    AddRandomSamples(*stub, argv[3], argv[4], samples, "add-", random);
  } else if (command == "list" && argc == 3) {
    List(*stub);
  } else if (command == "first-call" && argc == 5) {
    FirstCall(*stub, argv[3], argv[4]);
  } else {
    Fail(kUsage);
  }
  return 0;
}
