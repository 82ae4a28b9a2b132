// relmap stream: labelled feature vectors from a CSV file into a session, in batches.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "cli_commands.h"
#include "common/command_line.h"
#include "common/labelled_csv.h"
#include "progress_bar.h"

namespace relmap::client {
namespace {

// FNV-1a over the file: batch request ids derive from the content, so that streaming
// the same file again (after an interruption, say) adds nothing twice.
std::uint64_t ContentHash(const std::string& bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return hash;
}

v1::AddSamplesRequest Batch(const datasets::LabelledSamples& samples, Eigen::Index first,
                            Eigen::Index count) {
  v1::AddSamplesRequest request;
  for (Eigen::Index row = first; row < first + count; ++row) {
    v1::LabelledFeature* sample = request.add_samples();
    sample->set_label(samples.labels[static_cast<std::size_t>(row)] == 1 ? v1::LABEL_MOVEABLE
                                                                         : v1::LABEL_NOT_MOVEABLE);
    for (Eigen::Index j = 0; j < samples.features.cols(); ++j) {
      sample->mutable_feature()->add_values(samples.features(row, j));
    }
  }
  return request;
}

}  // namespace

int RunStream(const CommandLine& args) {
  args.Expect({"batch"}, 2);
  const SessionHandle session = SessionFrom(args, 0);
  const std::string& path = args.Positional(1, "samples.csv");
  const std::string bytes = ReadFileOrExit(path);
  std::istringstream in(bytes);
  const StatusOr<datasets::LabelledSamples> samples = datasets::ParseLabelledCsv(in, path);
  if (!samples.ok()) tools::ExitWithError("relmap", samples.status().message());
  const double batch_flag = args.Has("batch") ? args.Number("batch") : 500;
  if (!(batch_flag >= 1)) UsageError("--batch is at least 1");
  const auto batch = static_cast<Eigen::Index>(batch_flag);

  const std::unique_ptr<RelevanceClient> client = ClientFrom(args);
  const Eigen::Index total = samples->features.rows();
  char prefix[64];
  std::snprintf(prefix, sizeof prefix, "stream-%016llx-%lld-",
                static_cast<unsigned long long>(ContentHash(bytes)), static_cast<long long>(batch));
  ProgressBar progress("samples", static_cast<std::uint64_t>(total));
  v1::AddSamplesResponse response;
  for (Eigen::Index first = 0; first < total; first += batch) {
    v1::AddSamplesRequest request = Batch(*samples, first, std::min(batch, total - first));
    request.set_request_id(prefix + std::to_string(first / batch));
    const grpc::Status status = client->AddSamples(session, std::move(request), &response);
    if (!status.ok()) {
      progress.Finish();
      return PrintAnswer(status, response);
    }
    progress.Update(static_cast<std::uint64_t>(std::min(first + batch, total)));
  }
  progress.Finish();
  return PrintAnswer(grpc::Status::OK, response.stats());
}

}  // namespace relmap::client
