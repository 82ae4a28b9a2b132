// Decoding of uploaded clouds: PCD files (ascii, binary, binary_compressed) and the packed
// binary layout of the API. Everything is validated here, before any byte reaches PCL.
#pragma once

#include <cstdint>
#include <string_view>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/perception_config.h"

namespace relmap::perception {

// A PCD file (v0.6/v0.7) with fields x y z (float32 or float64) and rgb or rgba (4 bytes);
// other fields are skipped. Organized (HEIGHT > 1) or not. Errors are INVALID_ARGUMENT with
// a message naming the offending header line, size or value.
StatusOr<Cloud> DecodePcd(std::string_view bytes, const DecodeLimits& limits = {});

// The packed layout: per point float32 x, y, z then uint8 r, g, b, a (16 bytes, little
// endian), row-major, `width` x `height` points.
inline constexpr std::size_t kPackedPointBytes = 16;
StatusOr<Cloud> DecodePacked(std::string_view bytes, std::uint32_t width, std::uint32_t height,
                             const DecodeLimits& limits = {});

// Reads a whole file (bounded by limits.max_bytes) and decodes it as PCD.
StatusOr<Cloud> LoadPcdFile(const std::string& path, const DecodeLimits& limits = {});

}  // namespace relmap::perception
