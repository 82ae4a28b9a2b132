// A camera image's size in pixels, as the commands' --resolution gives it.
#pragma once

#include <cstdint>

namespace relmap::sim {

struct ImageSize {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
};

}  // namespace relmap::sim
