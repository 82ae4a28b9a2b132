#include "body_labels.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace relmap::sim {
namespace {

double SquaredDistance(const v1::Vector3& a, const v1::Vector3& b) {
  const double x = a.x() - b.x(), y = a.y() - b.y(), z = a.z() - b.z();
  return x * x + y * y + z * z;
}

}  // namespace

std::vector<std::uint32_t> BodyLabels(LabelScope scope, bool moveable,
                                      const v1::ComputeMapsResponse& maps, int index,
                                      const std::vector<int>& body) {
  std::size_t count = body.size();
  switch (scope) {
    case LabelScope::kTarget:
      return {};
    case LabelScope::kObject:
      break;
    case LabelScope::kMoved:
      if (!moveable) return {};
      break;
    case LabelScope::kNear:
      if (!moveable) count = std::min(count, kNearSupervoxels);
      break;
  }
  std::vector<std::uint32_t> ids;
  ids.reserve(count);
  if (count == body.size()) {  // in the body's order, as object labels always were posted
    for (const int j : body) ids.push_back(maps.supervoxels(j).id());
    return ids;
  }
  const v1::Vector3& target = maps.supervoxels(index).centroid();
  std::vector<std::pair<double, std::uint32_t>> by_distance;
  by_distance.reserve(body.size());
  for (const int j : body) {
    const v1::Supervoxel& other = maps.supervoxels(j);
    by_distance.emplace_back(SquaredDistance(other.centroid(), target), other.id());
  }
  std::partial_sort(by_distance.begin(), by_distance.begin() + static_cast<std::ptrdiff_t>(count),
                    by_distance.end());
  for (std::size_t i = 0; i < count; ++i) ids.push_back(by_distance[i].second);
  return ids;
}

}  // namespace relmap::sim
