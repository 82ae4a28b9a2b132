// The server marks a supervoxel with non-finite features by relevance 0.5 and choice 0
// (ComputeMapsResponse.unusable_supervoxels counts them) and refuses an outcome on one;
// the uniform draw leaves them out.
#include "target_choice.h"

#include <string>
#include <vector>

#include "seeds.h"

namespace relmap::sim {
namespace {

bool LooksUnusable(const v1::Supervoxel& s) { return s.relevance() == 0.5 && s.choice() == 0.0; }

}  // namespace

StatusOr<std::optional<int>> ChooseTarget(const v1::ComputeMapsResponse& maps,
                                          TargetSampling sampling, std::uint64_t random_bits) {
  if (sampling == TargetSampling::kChoice) {
    if (!maps.has_target_supervoxel_id()) return std::optional<int>();
    for (int i = 0; i < maps.supervoxels_size(); ++i) {
      if (maps.supervoxels(i).id() == maps.target_supervoxel_id()) return std::optional<int>(i);
    }
    return InvalidArgumentError("the server's target " +
                                std::to_string(maps.target_supervoxel_id()) +
                                " is not among its supervoxels");
  }
  std::vector<int> usable;
  for (int i = 0; i < maps.supervoxels_size(); ++i) {
    if (maps.unusable_supervoxels() == 0 || !LooksUnusable(maps.supervoxels(i))) {
      usable.push_back(i);
    }
  }
  if (usable.empty()) return std::optional<int>();
  return std::optional<int>(usable[UniformIndex(random_bits, usable.size())]);
}

}  // namespace relmap::sim
