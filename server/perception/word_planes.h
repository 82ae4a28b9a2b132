// Lossless compression of 32-bit words that are mostly small (residuals, labels): the
// words are split into byte planes (all lowest bytes, then the next, ...) so that the
// runs of zero high bytes lie together, then zstd packs the planes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/status.h"

namespace relmap::perception {

// zstd level 1: a 640x480 frame's residuals pack in a few milliseconds.
std::string PackWords(std::span<const std::uint32_t> words);

// The `count` words PackWords packed; DATA_LOSS when `packed` does not hold them.
StatusOr<std::vector<std::uint32_t>> UnpackWords(const std::string& packed, std::size_t count);

// A signed difference as a small unsigned word: 0, -1, 1, -2 ... → 0, 1, 2, 3 ...
inline std::uint32_t ZigZag(std::int32_t v) {
  return (static_cast<std::uint32_t>(v) << 1) ^ static_cast<std::uint32_t>(v >> 31);
}
inline std::int32_t UnZigZag(std::uint32_t w) {
  return static_cast<std::int32_t>((w >> 1) ^ (~(w & 1) + 1));
}

}  // namespace relmap::perception
