// The header of a PCD file, parsed and validated on its own (no PCL): field layout, declared
// sizes and counts, and where the data starts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"
#include "perception/perception_config.h"

namespace relmap::perception {

struct PcdField {
  std::string name;
  int size = 0;            // bytes of one element: 1, 2, 4 or 8
  char type = 0;           // 'F', 'I' or 'U'
  int count = 1;           // elements
  std::size_t offset = 0;  // bytes from the start of a point (binary layout)
  std::size_t bytes() const { return static_cast<std::size_t>(size) * count; }
};

enum class PcdData { kAscii, kBinary, kBinaryCompressed };

struct PcdHeader {
  std::vector<PcdField> fields;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::size_t points = 0;
  std::size_t point_bytes = 0;  // sum of the fields' bytes
  PcdData data = PcdData::kAscii;
  std::size_t data_offset = 0;  // first byte after the DATA line

  // Index of the field with this name, or -1.
  int Find(std::string_view name) const;
};

// Parses and checks the header: known keywords, one SIZE/TYPE/COUNT per field, legal
// sizes and types, WIDTH x HEIGHT == POINTS within limits.max_points.
StatusOr<PcdHeader> ParsePcdHeader(std::string_view bytes, const DecodeLimits& limits);

}  // namespace relmap::perception
