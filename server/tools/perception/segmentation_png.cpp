// A minimal PNG writer (8-bit RGB, zlib) and the segmentation rendering.
#include "segmentation_png.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <vector>

namespace relmap::perception {
namespace {

void PutU32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}

void Chunk(std::vector<unsigned char>& out, const char* type,
           const std::vector<unsigned char>& data) {
  PutU32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  PutU32(out, static_cast<std::uint32_t>(
                  crc32(0, out.data() + start, static_cast<uInt>(out.size() - start))));
}

Status WritePng(const std::string& path, std::uint32_t width, std::uint32_t height,
                const std::vector<std::array<std::uint8_t, 3>>& pixels) {
  std::vector<unsigned char> raw;  // each row: filter byte 0, then RGB
  raw.reserve((static_cast<std::size_t>(width) * 3 + 1) * height);
  for (std::uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);
    for (std::uint32_t x = 0; x < width; ++x) {
      const auto& p = pixels[static_cast<std::size_t>(y) * width + x];
      raw.insert(raw.end(), p.begin(), p.end());
    }
  }
  uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<unsigned char> packed(packed_size);
  if (compress(packed.data(), &packed_size, raw.data(), static_cast<uLong>(raw.size())) != Z_OK) {
    return InternalError("zlib compression failed");
  }
  packed.resize(packed_size);
  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> header;
  PutU32(header, width);
  PutU32(header, height);
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, no filter, no interlace
  Chunk(png, "IHDR", header);
  Chunk(png, "IDAT", packed);
  Chunk(png, "IEND", {});
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  if (!out) return InvalidArgumentError("cannot write '" + path + "'");
  return OkStatus();
}

std::array<std::uint8_t, 3> LabelColour(std::int32_t label) {
  if (label < 0) return {0, 0, 0};
  std::uint32_t h = static_cast<std::uint32_t>(label) * 2654435761u;  // Knuth's hash
  h ^= h >> 15;
  return {static_cast<std::uint8_t>(64 + (h & 0xbf)),
          static_cast<std::uint8_t>(64 + ((h >> 8) & 0xbf)),
          static_cast<std::uint8_t>(64 + ((h >> 16) & 0xbf))};
}

}  // namespace

Status WriteSegmentationPng(const Frame& frame, const std::string& path) {
  const Cloud& cloud = frame.cloud;
  const std::vector<std::int32_t>& labels = frame.segmentation.point_labels;
  if (cloud.organized()) {
    std::vector<std::array<std::uint8_t, 3>> pixels(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) pixels[i] = LabelColour(labels[i]);
    return WritePng(path, cloud.width(), cloud.height(), pixels);
  }
  // Top-down: x to the right, z (depth) upwards in the image, 800 px across the x-z extent.
  float min_x = INFINITY, max_x = -INFINITY, min_z = INFINITY, max_z = -INFINITY;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const CloudPoint p = cloud.point(i);
    if (!std::isfinite(p.x)) continue;
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_z = std::min(min_z, p.z), max_z = std::max(max_z, p.z);
  }
  const float extent = std::max({max_x - min_x, max_z - min_z, 1e-3f});
  const std::uint32_t size = 800;
  const float scale = static_cast<float>(size - 1) / extent;
  std::vector<std::array<std::uint8_t, 3>> pixels(static_cast<std::size_t>(size) * size);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const CloudPoint p = cloud.point(i);
    if (!std::isfinite(p.x)) continue;
    const auto x = static_cast<std::uint32_t>((p.x - min_x) * scale);
    const auto y = size - 1 - static_cast<std::uint32_t>((p.z - min_z) * scale);
    pixels[static_cast<std::size_t>(y) * size + x] = LabelColour(labels[i]);
  }
  return WritePng(path, size, size, pixels);
}

}  // namespace relmap::perception
