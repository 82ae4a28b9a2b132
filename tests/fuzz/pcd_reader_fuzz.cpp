// libFuzzer target: common/pcd's reader (ascii, binary, binary_compressed with LZF)
// on any bytes, with the server's decoding limits.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/pcd/pcd_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const auto points = relmap::pcd::ReadPcd(bytes, relmap::pcd::ReadLimits{});
  if (points.ok() &&
      points->points.size() != static_cast<std::size_t>(points->width) * points->height) {
    __builtin_trap();  // the reader promises width x height points
  }
  return 0;
}
