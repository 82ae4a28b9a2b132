// libFuzzer target: a scene file's JSON, parsed and validated (sim_backend/scene_file.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view json(reinterpret_cast<const char*>(data), size);
  (void)relmap::sim::ParseScene(json, "fuzz.json");
  return 0;
}
