// libFuzzer target: relmap-robot's config (robot_adapter/robot_config.h). The first
// byte chooses the syntax: even JSON, odd YAML; the rest is the file.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_input.h"
#include "robot_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  relmap::fuzz::FuzzInput input(data, size);
  const bool yaml = (input.Byte() & 1) != 0;
  if (yaml) {
    (void)relmap::robot::ParseRobotConfigYaml(input.Rest(), "fuzz.yaml");
  } else {
    (void)relmap::robot::ParseRobotConfig(input.Rest(), "fuzz.json");
  }
  return 0;
}
