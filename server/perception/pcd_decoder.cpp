// PCD files to a Cloud: common/pcd reads the points (the same reader the CLI renders
// with), MakeCloud applies the server's checks.
#include <string>

#include "common/pcd/pcd_reader.h"
#include "perception/decode.h"

namespace relmap::perception {
namespace {

pcd::ReadLimits ReadLimitsOf(const DecodeLimits& limits) {
  return {static_cast<std::uint64_t>(limits.max_points),
          static_cast<std::uint64_t>(limits.max_bytes)};
}

}  // namespace

StatusOr<Cloud> DecodePcd(std::string_view bytes, const DecodeLimits& limits) {
  StatusOr<pcd::Points> read = pcd::ReadPcd(bytes, ReadLimitsOf(limits));
  if (!read.ok()) return read.status();
  return MakeCloud(read->width, read->height, std::move(read->points), limits);
}

StatusOr<Cloud> LoadPcdFile(const std::string& path, const DecodeLimits& limits) {
  StatusOr<std::string> bytes = pcd::ReadFileBytes(path, ReadLimitsOf(limits).max_bytes);
  if (!bytes.ok()) return bytes.status();
  StatusOr<Cloud> cloud = DecodePcd(*bytes, limits);
  if (!cloud.ok()) return Status(cloud.status().code(), path + ": " + cloud.status().message());
  return cloud;
}

}  // namespace relmap::perception
