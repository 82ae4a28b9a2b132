// libFuzzer target: the PCD header parser, both as a stream reader calls it (a
// prefix that may end before DATA) and as a whole file's.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/pcd/pcd_header.h"
#include "common/pcd/pcd_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::uint64_t max_points = relmap::pcd::ReadLimits{}.max_points;
  const auto prefix = relmap::pcd::ParseHeaderPrefix(bytes, max_points);
  if (prefix.ok() && prefix->has_value() && (*prefix)->data_offset > bytes.size()) {
    __builtin_trap();  // the data cannot start beyond the bytes parsed
  }
  const auto header = relmap::pcd::ParseHeader(bytes, max_points);
  if (header.ok() && header->points != std::size_t{header->width} * header->height) {
    __builtin_trap();
  }
  return 0;
}
