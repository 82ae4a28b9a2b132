// relmap maps and relmap outcome: one push cycle from the command line.
#include "cli_commands.h"
#include "common/command_line.h"
#include "common/pcd/pcd_reader.h"
#include "map_rendering_pcd.h"

namespace relmap::client {
namespace {

// The renderings asked for, drawn over the cloud as this client reads it, with the
// same PCD reader as the server's decoder so that the point labels line up.
void WriteRenderings(const CommandLine& args, const std::string& pcd_bytes,
                     const v1::ComputeMapsResponse& maps) {
  const StatusOr<pcd::Points> cloud = pcd::ReadPcd(pcd_bytes);
  if (!cloud.ok()) tools::ExitWithError("relmap", cloud.status().message());
  const auto check = [](const Status& written) {
    if (!written.ok()) tools::ExitWithError("relmap", written.message());
  };
  if (args.Has("png")) check(WriteMapPng(*cloud, maps, MapKind::kRelevance, args.Get("png")));
  if (args.Has("choice-png")) {
    check(WriteMapPng(*cloud, maps, MapKind::kChoice, args.Get("choice-png")));
  }
  if (args.Has("pcd")) check(WriteRelevancePcd(*cloud, maps, args.Get("pcd")));
}

}  // namespace

int RunMaps(const CommandLine& args) {
  args.Expect({"png", "choice-png", "pcd"}, 2);
  const SessionHandle session = SessionFrom(args, 0);
  const std::string pcd = ReadFileOrExit(args.Positional(1, "cloud.pcd"));
  const std::unique_ptr<RelevanceClient> client = ClientFrom(args);
  // The labels of the points (one per pixel) serve the renderings, not the terminal.
  const bool render = args.Has("png") || args.Has("choice-png") || args.Has("pcd");
  v1::ComputeMapsResponse maps;
  const grpc::Status status = client->ComputeMaps(
      session, PcdCloud(pcd), &maps, render ? PointLabels::kInclude : PointLabels::kOmit);
  if (status.ok() && render) WriteRenderings(args, pcd, maps);
  maps.clear_point_labels();
  return PrintAnswer(status, maps);
}

int RunOutcome(const CommandLine& args) {
  args.Expect({"request-id", "after-cloud"}, 4);
  const SessionHandle session = SessionFrom(args, 0);
  const auto frame = static_cast<std::uint64_t>(
      tools::ParseNumberOrExit("relmap", "<frame>", args.Positional(1, "frame").c_str()));
  const auto supervoxel = static_cast<std::uint32_t>(
      tools::ParseNumberOrExit("relmap", "<supervoxel>", args.Positional(2, "supervoxel").c_str()));
  const std::string request_id = args.Get("request-id");
  const std::unique_ptr<RelevanceClient> client = ClientFrom(args);
  v1::PostOutcomeResponse response;
  if (args.Has("after-cloud")) {
    if (args.positional_count() > 3) UsageError("give moved|still or --after-cloud, not both");
    const v1::Cloud after = PcdCloud(ReadFileOrExit(args.Get("after-cloud")));
    return PrintAnswer(
        client->PostOutcome(session, frame, supervoxel, after, request_id, &response), response);
  }
  const std::string& outcome = args.Positional(3, "moved|still");
  if (outcome != "moved" && outcome != "still") {
    UsageError("the outcome is moved or still, not '" + outcome + "'");
  }
  const v1::Label label = outcome == "moved" ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE;
  return PrintAnswer(client->PostOutcome(session, frame, supervoxel, label, request_id, &response),
                     response);
}

}  // namespace relmap::client
