// Whole-run figure for the server's durability: N one-sample AddSamples calls of
// the 48-d XOR-blobs stream into a new session of a running relmap-server, timed.
// Restart the server on the same --data-dir afterwards; its log gives the replay
// time ("restored session=... samples=N in T ms").
//   durable_samples_probe 127.0.0.1:50051 1000 [corrected|paper2018]
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "common/command_line.h"
#include "datasets/synthetic_problems.h"
#include "relmap/v1/relevance_service.grpc.pb.h"

int main(int argc, char** argv) {
  using namespace relmap;
  if (argc < 3)
    tools::ExitWithError("durable_samples_probe", "usage: ADDRESS N [corrected|paper2018]");
  const auto n = static_cast<int>(tools::ParseNumberOrExit("durable_samples_probe", "N", argv[2]));
  auto stub = v1::RelevanceService::NewStub(
      grpc::CreateChannel(argv[1], grpc::InsecureChannelCredentials()));
  grpc::ClientContext create_context;
  v1::CreateSessionRequest create;
  create.mutable_config()->set_seed(1);
  if (argc > 3 && std::string(argv[3]) == "paper2018") {
    create.mutable_config()->mutable_classifier()->set_variant(v1::CLASSIFIER_VARIANT_PAPER2018);
  }
  v1::CreateSessionResponse created;
  if (const grpc::Status s = stub->CreateSession(&create_context, create, &created); !s.ok()) {
    tools::ExitWithError("durable_samples_probe", s.error_message());
  }
  datasets::ProblemOptions options;
  options.problem = datasets::Problem::kXorBlobs;
  options.dimension = 48;
  options.samples = n;
  options.seed = 1;
  const datasets::LabelledSamples stream = datasets::MakeProblem(options);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    grpc::ClientContext context;
    context.AddMetadata("authorization", "Bearer " + created.session_token());
    v1::AddSamplesRequest request;
    request.set_session_id(created.session_id());
    request.set_request_id("sample-" + std::to_string(i));
    v1::LabelledFeature* sample = request.add_samples();
    for (Eigen::Index k = 0; k < stream.features.cols(); ++k) {
      sample->mutable_feature()->add_values(stream.features(i, k));
    }
    sample->set_label(stream.labels[i] == 1 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
    v1::AddSamplesResponse response;
    if (const grpc::Status s = stub->AddSamples(&context, request, &response); !s.ok()) {
      tools::ExitWithError("durable_samples_probe", s.error_message());
    }
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("session %s: %d durable AddSamples calls, %.3f ms per call\n",
              created.session_id().c_str(), n, ms / n);
  return 0;
}
