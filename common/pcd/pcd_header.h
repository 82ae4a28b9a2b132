// The header of a PCD file (v0.6/v0.7), parsed and validated on its own: field layout,
// declared sizes and counts, and where the data starts. One parser for every reader of
// PCD in relmap: the server's decoder, the CLI, and relmap-robot's stream framing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/status.h"

namespace relmap::pcd {

struct Field {
  std::string name;
  int size = 0;            // bytes of one element: 1, 2, 4 or 8
  char type = 0;           // 'F', 'I' or 'U'
  int count = 1;           // elements
  std::size_t offset = 0;  // bytes from the start of a point (binary layout)
  std::size_t bytes() const { return static_cast<std::size_t>(size) * count; }
};

enum class DataKind { kAscii, kBinary, kBinaryCompressed };

struct Header {
  std::vector<Field> fields;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::size_t points = 0;
  std::size_t point_bytes = 0;  // sum of the fields' bytes
  DataKind data = DataKind::kAscii;
  std::size_t data_offset = 0;  // first byte after the DATA line

  // Index of the field with this name, or -1.
  int Find(std::string_view name) const;
};

// The layout of the header at the start of `bytes`: known keywords, one SIZE/TYPE/COUNT
// per field, legal sizes and types, WIDTH x HEIGHT == POINTS, at most `max_points`
// (RESOURCE_EXHAUSTED beyond). nullopt while `bytes` ends before the DATA line's newline,
// so a stream reader can wait for more; other errors are INVALID_ARGUMENT naming the line.
StatusOr<std::optional<Header>> ParseHeaderPrefix(std::string_view bytes, std::uint64_t max_points);

// The header of a whole file, which must also hold the point fields relmap reads:
// x, y, z as single floats and one 4-byte rgb or rgba.
StatusOr<Header> ParseHeader(std::string_view bytes, std::uint64_t max_points);

}  // namespace relmap::pcd
