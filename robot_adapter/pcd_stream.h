// PCD files one after another on a pipe or a socket (`cat a.pcd b.pcd | …`), cut
// into frames. Each header says how long its data is — POINTS lines (ascii), POINTS ×
// the point's bytes (binary), or the compressed size in the data's first four bytes
// (binary_compressed) — so no extra framing is needed. Only framing: the server
// decodes and checks the clouds.
#pragma once

#include <atomic>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "common/pcd/pcd_header.h"
#include "common/status.h"
#include "posix_io.h"

namespace relmap::robot {

// Where the data of a PCD file ends, from its header (common/pcd's parser).
struct PcdFraming {
  pcd::DataKind data = pcd::DataKind::kAscii;
  std::size_t header_bytes = 0;  // up to and including the DATA line
  std::size_t points = 0;
  std::size_t point_bytes = 0;  // sum of SIZE × COUNT
};

// The framing of the PCD header at the start of `bytes`; nullopt when `bytes` ends
// before the DATA line's end. INVALID_ARGUMENT when it is not a valid PCD header, or
// declares more than `max_frame_bytes` of data.
StatusOr<std::optional<PcdFraming>> ParsePcdFraming(std::string_view bytes,
                                                    std::size_t max_frame_bytes);

class PcdStream {
 public:
  static constexpr std::size_t kMaxFrameBytes = std::size_t{1} << 29;  // 512 MiB

  // Reads `fd`, which it does not own. `stop`, when set, ends a wait for bytes.
  PcdStream(int fd, const std::atomic<bool>* stop);

  // The next PCD file of the stream, its header and data to the byte (NUL or white
  // space between files, as PCL pads its binary_compressed files with, is skipped).
  // nullopt at the end of the stream between two files, or when stopped or past
  // `deadline` (what was read of a file is kept for the next call); DATA_LOSS when the
  // stream ends inside a file; INVALID_ARGUMENT when a header is not PCD.
  StatusOr<std::optional<std::string>> Next(Clock::time_point deadline = Clock::time_point::max());
  // Whether the stream has reached its end.
  bool ended() const { return ended_; }

 private:
  // Reads until the buffer holds `size` bytes; false at the end of the stream, on a
  // stop or past the deadline.
  StatusOr<bool> Fill(std::size_t size);
  // The length of the data of `framing` (after its header), reading as far as needed
  // to know it; false as Fill.
  StatusOr<bool> DataBytes(const PcdFraming& framing, std::size_t* bytes);

  int fd_;
  const std::atomic<bool>* stop_;
  std::string buffer_;
  Clock::time_point deadline_ = Clock::time_point::max();
  bool ended_ = false;
};

}  // namespace relmap::robot
