// Synthetic and decimated clouds are packed, so that every repeat decodes them like
// an upload.
#include "cloud_input.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "perception/decode.h"
#include "perception/synthetic_tabletop.h"

namespace relmap::tools {
namespace {

bool ReadFile(const std::string& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  bytes = s.str();
  return true;
}

// The packed encoding of a cloud (DecodePacked's input).
std::string PackedBytes(const std::vector<perception::CloudPoint>& points) {
  std::string bytes;
  for (const perception::CloudPoint& p : points) {
    const char* raw = reinterpret_cast<const char*>(&p.x);
    bytes.append(raw, 12);
    bytes.append({static_cast<char>(p.r), static_cast<char>(p.g), static_cast<char>(p.b),
                  static_cast<char>(p.a)});
  }
  return bytes;
}

// "synthetic:640x480" -> the packed encoding of a synthetic tabletop.
bool SyntheticBytes(const std::string& spec, CloudInput& input) {
  if (std::sscanf(spec.c_str(), "synthetic:%ux%u", &input.width, &input.height) != 2) {
    return false;
  }
  perception::SyntheticTabletopOptions options;
  options.width = input.width, options.height = input.height;
  input.bytes = PackedBytes(perception::MakeSyntheticTabletop(options).cloud.points());
  input.packed = true;
  return true;
}

// Every `stride`-th column and row of the organized PCD file in `input.bytes`, packed.
bool Decimate(std::uint32_t stride, CloudInput& input) {
  auto cloud = perception::DecodePcd(input.bytes);
  if (!cloud.ok() || !cloud->organized()) return false;
  const std::vector<perception::CloudPoint> points = cloud->points();
  input.width = cloud->width() / stride, input.height = cloud->height() / stride;
  std::vector<perception::CloudPoint> kept;
  for (std::uint32_t v = 0; v < input.height; ++v) {
    for (std::uint32_t u = 0; u < input.width; ++u) {
      kept.push_back(points[static_cast<std::size_t>(v) * stride * cloud->width() +
                            static_cast<std::size_t>(u) * stride]);
    }
  }
  input.bytes = PackedBytes(kept);
  input.packed = true;
  return true;
}

}  // namespace

StatusOr<perception::Cloud> CloudInput::Decode(const perception::DecodeLimits& limits) const {
  return packed ? perception::DecodePacked(bytes, width, height, limits)
                : perception::DecodePcd(bytes, limits);
}

StatusOr<CloudInput> ReadCloudInput(const std::string& input, std::uint32_t stride) {
  CloudInput cloud;
  const bool synthetic = input.rfind("synthetic:", 0) == 0;
  if (synthetic ? !SyntheticBytes(input, cloud) : !ReadFile(input, cloud.bytes)) {
    return InvalidArgumentError("cannot read '" + input + "'");
  }
  if (!synthetic && stride > 1 && !Decimate(stride, cloud)) {
    return InvalidArgumentError("--stride needs an organized PCD cloud: '" + input + "'");
  }
  return cloud;
}

}  // namespace relmap::tools
