// The LZF stream is a sequence of runs, each introduced by a control byte c:
//   c < 32:  a literal run of c + 1 bytes that follow;
//   c >= 32: a back reference of length (c >> 5) + 2, extended by the next byte when
//            c >> 5 == 7, at distance ((c & 31) << 8) + next byte + 1 behind the output.
// A reference may overlap the bytes it produces (a run of one repeated byte), so it is
// copied byte by byte.
#include "common/pcd/lzf.h"

#include <cstdint>
#include <cstring>

namespace relmap::pcd {

std::size_t LzfDecompress(std::string_view in, char* out, std::size_t out_size) {
  const auto* ip = reinterpret_cast<const std::uint8_t*>(in.data());
  std::size_t i = 0;  // next input byte
  std::size_t o = 0;  // next output byte
  while (i < in.size()) {
    const std::size_t control = ip[i++];
    if (control < 32) {
      const std::size_t length = control + 1;
      if (length > in.size() - i || length > out_size - o) return 0;
      std::memcpy(out + o, ip + i, length);
      i += length;
      o += length;
      continue;
    }
    std::size_t length = control >> 5;
    if (i >= in.size()) return 0;
    if (length == 7) {
      length += ip[i++];
      if (i >= in.size()) return 0;
    }
    const std::size_t distance = ((control & 31) << 8) + ip[i++] + 1;
    length += 2;
    if (distance > o || length > out_size - o) return 0;
    for (std::size_t k = 0; k < length; ++k, ++o) out[o] = out[o - distance];
  }
  return o;
}

}  // namespace relmap::pcd
