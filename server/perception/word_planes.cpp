// Byte planes and zstd.
#include "perception/word_planes.h"

#include <zstd.h>

namespace relmap::perception {
namespace {

constexpr int kZstdLevel = 1;

}  // namespace

std::string PackWords(std::span<const std::uint32_t> words) {
  const std::size_t n = words.size();
  std::string planes(4 * n, '\0');
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t b = 0; b < 4; ++b) {
      planes[b * n + i] = static_cast<char>((words[i] >> (8 * b)) & 0xffU);
    }
  }
  std::string packed(ZSTD_compressBound(planes.size()), '\0');
  const std::size_t size =
      ZSTD_compress(packed.data(), packed.size(), planes.data(), planes.size(), kZstdLevel);
  // Only an undersized destination or an allocation failure makes zstd fail, and the
  // destination has zstd's own bound.
  packed.resize(ZSTD_isError(size) != 0 ? 0 : size);
  packed.shrink_to_fit();
  return packed;
}

StatusOr<std::vector<std::uint32_t>> UnpackWords(const std::string& packed, std::size_t count) {
  std::string planes(4 * count, '\0');
  const std::size_t size =
      ZSTD_decompress(planes.data(), planes.size(), packed.data(), packed.size());
  if (ZSTD_isError(size) != 0 || size != planes.size()) {
    return DataLossError("packed words do not unpack to " + std::to_string(count) + " words");
  }
  std::vector<std::uint32_t> words(count, 0);
  for (std::size_t b = 0; b < 4; ++b) {
    for (std::size_t i = 0; i < count; ++i) {
      words[i] |= static_cast<std::uint32_t>(static_cast<unsigned char>(planes[b * count + i]))
                  << (8 * b);
    }
  }
  return words;
}

}  // namespace relmap::perception
