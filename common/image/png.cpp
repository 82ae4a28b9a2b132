// PNG encoding (signature, IHDR, one zlib IDAT, IEND) with zlib's deflate and CRC.
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <vector>

#include "common/image/image.h"

namespace relmap::image {
namespace {

void PutU32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<unsigned char>(v >> shift));
}

void PutChunk(std::vector<unsigned char>& out, const char* type,
              const std::vector<unsigned char>& data) {
  PutU32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  PutU32(out, static_cast<std::uint32_t>(
                  crc32(0, out.data() + start, static_cast<uInt>(out.size() - start))));
}

}  // namespace

Status WritePng(const Image& image, const std::string& path) {
  const auto width = static_cast<std::uint32_t>(image.width());
  const auto height = static_cast<std::uint32_t>(image.height());
  std::vector<unsigned char> raw;  // per row: filter type 0, then RGB
  raw.reserve((static_cast<std::size_t>(width) * 3 + 1) * height);
  for (std::uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);
    for (std::uint32_t x = 0; x < width; ++x) {
      const Rgb& p = image.pixels()[static_cast<std::size_t>(y) * width + x];
      raw.insert(raw.end(), p.begin(), p.end());
    }
  }
  uLongf compressed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<unsigned char> compressed(compressed_size);
  if (compress2(compressed.data(), &compressed_size, raw.data(), static_cast<uLong>(raw.size()),
                Z_BEST_SPEED) != Z_OK) {
    return InternalError("zlib could not compress the image for " + path);
  }
  compressed.resize(compressed_size);

  std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> header;
  PutU32(header, width);
  PutU32(header, height);
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, no filter, no interlace
  PutChunk(png, "IHDR", header);
  PutChunk(png, "IDAT", compressed);
  PutChunk(png, "IEND", {});

  std::ofstream out(path, std::ios::binary);
  if (!out) return NotFoundError("cannot write " + path);
  out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  return out ? OkStatus() : DataLossError("write to " + path + " failed");
}

}  // namespace relmap::image
