// libFuzzer target: the packed cloud layout of the API (perception::DecodePacked).
// Input: u32 width, u32 height (little endian), then the points' bytes.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_input.h"
#include "perception/decode.h"

namespace {

// Every point the decoder accepts is a hole or lies within the limits (decode.h).
void CheckCloud(const relmap::perception::Cloud& cloud,
                const relmap::perception::DecodeLimits& limits) {
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto point = cloud.point(i);
    if (!std::isfinite(point.x)) continue;
    if (std::abs(point.x) > limits.max_abs_coordinate ||
        std::abs(point.y) > limits.max_abs_coordinate ||
        std::abs(point.z) > limits.max_abs_coordinate) {
      __builtin_trap();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  relmap::fuzz::FuzzInput input(data, size);
  const std::uint32_t width = input.U32();
  const std::uint32_t height = input.U32();
  const relmap::perception::DecodeLimits limits;
  const auto cloud = relmap::perception::DecodePacked(input.Rest(), width, height, limits);
  if (cloud.ok()) CheckCloud(*cloud, limits);
  return 0;
}
