// The samples a chaos session adds with AddSamples: 48-d vectors in [0, 1] drawn
// around two centres per label, so that the classifier learns a few components and
// its cost stays small (random unclustered vectors make learning slow, issue 14
// item 4, which is not what a chaos run measures). Every vector is new, so a stored
// sample names the request it came from.
#pragma once

#include <cstdint>

#include "common/random.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::chaos {

class LabelledStream {
 public:
  // The centres are the same for every seed (one scene); `seed` draws the samples.
  explicit LabelledStream(std::uint64_t seed);

  // The next sample: labels alternate, a centre of its label at random, each value
  // the centre's ± 0.05.
  v1::LabelledFeature Next();

 private:
  Random random_;
  std::uint64_t drawn_ = 0;
};

}  // namespace relmap::chaos
