// Majority vote of the target's points; a seeded coin.
#include "outcome_label.h"

#include <map>

#include "common/random.h"

namespace relmap::load {

std::optional<v1::Label> GroundTruthLabel(const v1::ComputeMapsResponse& maps,
                                          const std::vector<int>& object_of_point) {
  if (static_cast<std::size_t>(maps.point_labels_size()) != object_of_point.size()) {
    return std::nullopt;
  }
  const auto target = static_cast<std::int32_t>(maps.target_supervoxel_id());
  std::map<int, std::size_t> votes;  // object id → points of the target on it
  for (int i = 0; i < maps.point_labels_size(); ++i) {
    if (maps.point_labels(i) == target) ++votes[object_of_point[static_cast<std::size_t>(i)]];
  }
  int majority = 0;
  std::size_t most = 0;
  for (const auto& [object, points] : votes) {
    if (object >= 0 && points > most) majority = object, most = points;
  }
  return majority >= 1 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE;
}

v1::Label CoinLabel(std::uint64_t session_seed, std::uint64_t cycle) {
  return (SplitMix64Mix(session_seed ^ SplitMix64Mix(cycle)) & 1) != 0 ? v1::LABEL_MOVEABLE
                                                                       : v1::LABEL_NOT_MOVEABLE;
}

}  // namespace relmap::load
