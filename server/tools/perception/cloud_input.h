// The cloud relmap-perception times, as the bytes a client would upload: a PCD
// file, a synthetic tabletop or a decimated organized PCD (both packed).
#pragma once

#include <cstdint>
#include <string>

#include "common/status.h"
#include "perception/cloud.h"
#include "perception/perception_config.h"

namespace relmap::tools {

struct CloudInput {
  std::string bytes;
  bool packed = false;  // the packed layout (width x height), else a PCD file
  std::uint32_t width = 0;
  std::uint32_t height = 0;

  // The cloud of the bytes, decoded as an upload would be.
  StatusOr<perception::Cloud> Decode(const perception::DecodeLimits& limits) const;
};

// `input`: a PCD file or "synthetic:WxH"; with `stride` > 1, every stride-th column
// and row of an organized PCD file: what a camera of 1/stride the resolution sees of
// the same scene (320x240 from a 640x480 recording).
StatusOr<CloudInput> ReadCloudInput(const std::string& input, std::uint32_t stride);

}  // namespace relmap::tools
