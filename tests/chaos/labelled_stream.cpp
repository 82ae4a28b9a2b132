// Centres from a fixed SplitMix64 stream, samples from the session's generator.
#include "chaos/labelled_stream.h"

#include <algorithm>

namespace relmap::chaos {
namespace {

constexpr std::uint64_t kDimension = 48;  // the server's default feature dimension
constexpr std::uint64_t kCentresPerLabel = 2;
constexpr double kSpread = 0.05;

// Value `k` of centre `centre` of `label`, in [0.2, 0.8].
double CentreValue(std::uint64_t label, std::uint64_t centre, std::uint64_t k) {
  return 0.2 +
         0.6 * UnitFromBits(SplitMix64At((label * kCentresPerLabel + centre) * kDimension + k));
}

}  // namespace

LabelledStream::LabelledStream(std::uint64_t seed) : random_(seed) {}

v1::LabelledFeature LabelledStream::Next() {
  const std::uint64_t label = drawn_++ % 2;
  const std::uint64_t centre = random_.UniformIndex(kCentresPerLabel);
  v1::LabelledFeature sample;
  sample.set_label(label == 1 ? v1::LABEL_MOVEABLE : v1::LABEL_NOT_MOVEABLE);
  for (std::uint64_t k = 0; k < kDimension; ++k) {
    const double value = CentreValue(label, centre, k) + kSpread * (2 * random_.UniformUnit() - 1);
    sample.mutable_feature()->add_values(std::clamp(value, 0.0, 1.0));
  }
  return sample;
}

}  // namespace relmap::chaos
