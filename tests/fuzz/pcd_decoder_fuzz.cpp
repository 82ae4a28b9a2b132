// libFuzzer target: the server's PCD decoder (perception::DecodePcd), which
// validates a file before its points become a PCL cloud.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "perception/decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const auto cloud = relmap::perception::DecodePcd(bytes, relmap::perception::DecodeLimits{});
  if (cloud.ok() && cloud->valid_points() > cloud->size()) __builtin_trap();
  return 0;
}
