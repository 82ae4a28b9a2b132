// Hand-made organized clouds for the change detector's tests: a 160 x 120 pinhole camera
// with a 140-pixel focal length, each pixel's depth given by a function.
#pragma once

#include <cstdint>
#include <vector>

#include "perception/cloud.h"

namespace relmap::perception::testing {

constexpr std::uint32_t kWidth = 160, kHeight = 120;
constexpr float kFocal = 140.0f;

// The cloud whose pixel (u, v) lies at depth `depth(u, v)` metres (NaN: a hole).
template <typename Depth>
Cloud PinholeCloud(Depth depth) {
  std::vector<CloudPoint> points(static_cast<std::size_t>(kWidth) * kHeight);
  for (std::uint32_t v = 0; v < kHeight; ++v) {
    for (std::uint32_t u = 0; u < kWidth; ++u) {
      const float z = depth(u, v);
      CloudPoint& p = points[static_cast<std::size_t>(v) * kWidth + u];
      p.x = (static_cast<float>(u) - (kWidth - 1) / 2.0f) * z / kFocal;
      p.y = (static_cast<float>(v) - (kHeight - 1) / 2.0f) * z / kFocal;
      p.z = z;
    }
  }
  return *MakeCloud(kWidth, kHeight, points);
}

}  // namespace relmap::perception::testing
