// The camera frame as plain coloured points for client/map_rendering.h.
#include "map_snapshots.h"

#include <vector>

#include "map_rendering.h"

namespace relmap::sim {

Status WriteMapSnapshots(const CameraFrame& frame, const v1::ComputeMapsResponse& maps,
                         const std::string& directory, int replication, int iteration) {
  std::vector<image::ColouredPoint> points(frame.points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CameraPoint& p = frame.points[i];
    points[i] = {p.x, p.y, p.z, {p.r, p.g, p.b}};
  }
  // Appended piece by piece: GCC 12 takes "-" + std::string for an overlapping memcpy
  // (a false -Wrestrict).
  std::string suffix = "-";
  suffix += std::to_string(replication);
  suffix += '-';
  suffix += std::to_string(iteration);
  for (const auto& [kind, name] : {std::pair{client::MapKind::kRelevance, "relevance"},
                                   std::pair{client::MapKind::kChoice, "choice"}}) {
    std::string path = directory;
    path += '/';
    path += name;
    path += suffix;
    path += ".png";
    if (Status written = client::WriteMapPng(frame.width, frame.height, points, maps, kind, path);
        !written.ok()) {
      return Status(written.code(), path + ": " + written.message());
    }
  }
  return OkStatus();
}

}  // namespace relmap::sim
