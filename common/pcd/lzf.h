// LZF decompression (Marc Lehmann's liblzf format), the codec of PCD's
// binary_compressed data, written here so that reading a PCD needs no PCL.
#pragma once

#include <cstddef>
#include <string_view>

namespace relmap::pcd {

// Decompresses `in` into out[0, out_size). Returns the bytes written, or 0 when the data
// is corrupt or would not fit: every read and write is checked against both buffers.
std::size_t LzfDecompress(std::string_view in, char* out, std::size_t out_size);

}  // namespace relmap::pcd
