// Cutting a stream of PCD files into frames.
#include "pcd_stream.h"

#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace relmap::robot {
namespace {

bool IsGap(char c) { return c == '\0' || c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

bool IsBlank(std::string_view line) { return line.find_first_not_of(" \t\r") == line.npos; }

}  // namespace

StatusOr<std::optional<PcdFraming>> ParsePcdFraming(std::string_view bytes,
                                                    std::size_t max_frame_bytes) {
  // Every point takes at least a byte, so a frame's bytes bound its points.
  StatusOr<std::optional<pcd::Header>> header = pcd::ParseHeaderPrefix(bytes, max_frame_bytes);
  if (!header.ok()) {
    return InvalidArgumentError("the stream does not hold a PCD file here: " +
                                header.status().message());
  }
  if (!header->has_value()) return std::optional<PcdFraming>();
  const pcd::Header& h = **header;
  // No overflow: points <= max_frame_bytes and point_bytes <= 256 fields x 4096 x 8.
  if (h.points * h.point_bytes > max_frame_bytes) {
    return InvalidArgumentError("PCD header declares " + std::to_string(h.points) + " points of " +
                                std::to_string(h.point_bytes) + " bytes, more than a frame's " +
                                "limit of " + std::to_string(max_frame_bytes) + " bytes");
  }
  return std::optional<PcdFraming>(PcdFraming{h.data, h.data_offset, h.points, h.point_bytes});
}

PcdStream::PcdStream(int fd, const std::atomic<bool>* stop) : fd_(fd), stop_(stop) {}

StatusOr<bool> PcdStream::Fill(std::size_t size) {
  while (buffer_.size() < size) {
    if (ended_) return false;
    StatusOr<Wait> ready = WaitReadable(fd_, deadline_, stop_);
    if (!ready.ok()) return ready.status();
    if (*ready != Wait::kReady) return false;
    char chunk[64 * 1024];
    const ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0 && errno != ECONNRESET) {
      return Status(StatusCode::kUnavailable, std::string("read: ") + std::strerror(errno));
    }
    if (n <= 0) {
      ended_ = true;
      return false;
    }
    buffer_.append(chunk, static_cast<std::size_t>(n));
  }
  return true;
}

StatusOr<bool> PcdStream::DataBytes(const PcdFraming& framing, std::size_t* bytes) {
  const std::size_t start = framing.header_bytes;
  switch (framing.data) {
    case pcd::DataKind::kBinary:
      *bytes = framing.points * framing.point_bytes;
      return true;
    case pcd::DataKind::kBinaryCompressed: {
      // PCL's layout: uint32 compressed size, uint32 uncompressed size, the LZF data.
      StatusOr<bool> filled = Fill(start + 8);
      if (!filled.ok() || !*filled) return filled;
      std::uint32_t compressed = 0;
      std::memcpy(&compressed, buffer_.data() + start, sizeof compressed);
      if (compressed > kMaxFrameBytes) {
        return InvalidArgumentError("binary_compressed PCD declares " + std::to_string(compressed) +
                                    " compressed bytes, more than a frame's limit");
      }
      *bytes = 8 + std::size_t{compressed};
      return true;
    }
    case pcd::DataKind::kAscii:
      break;
  }
  // One non-empty line per point; the last one may end with the stream.
  std::size_t lines = 0;
  std::size_t position = start;
  while (lines < framing.points) {
    const std::size_t end = buffer_.find('\n', position);
    if (end == std::string::npos) {
      if (buffer_.size() - start > kMaxFrameBytes) {
        return InvalidArgumentError("ascii PCD data longer than a frame's limit");
      }
      StatusOr<bool> filled = Fill(buffer_.size() + 1);
      if (!filled.ok()) return filled;
      if (*filled) continue;
      if (ended_ && lines + 1 == framing.points && position < buffer_.size()) {
        *bytes = buffer_.size() - start;
        return true;
      }
      return false;
    }
    if (!IsBlank(std::string_view(buffer_).substr(position, end - position))) ++lines;
    position = end + 1;
  }
  *bytes = position - start;
  return true;
}

StatusOr<std::optional<std::string>> PcdStream::Next(Clock::time_point deadline) {
  deadline_ = deadline;
  // Whatever lies between two files: PCL pads binary_compressed files with NULs.
  for (;;) {
    std::size_t gap = 0;
    while (gap < buffer_.size() && IsGap(buffer_[gap])) ++gap;
    buffer_.erase(0, gap);
    if (!buffer_.empty()) break;
    StatusOr<bool> filled = Fill(1);
    if (!filled.ok()) return filled.status();
    if (!*filled) return std::optional<std::string>();
  }
  std::optional<PcdFraming> framing;
  for (;;) {
    StatusOr<std::optional<PcdFraming>> parsed = ParsePcdFraming(buffer_, kMaxFrameBytes);
    if (!parsed.ok()) return parsed.status();
    if (parsed->has_value()) {
      framing = **parsed;
      break;
    }
    StatusOr<bool> filled = Fill(buffer_.size() + 1);
    if (!filled.ok()) return filled.status();
    if (!*filled) break;
  }
  std::size_t data_bytes = 0;
  if (framing) {
    StatusOr<bool> known = DataBytes(*framing, &data_bytes);
    if (!known.ok()) return known.status();
    if (*known) {
      StatusOr<bool> filled = Fill(framing->header_bytes + data_bytes);
      if (!filled.ok()) return filled.status();
      if (*filled) {
        std::string frame = buffer_.substr(0, framing->header_bytes + data_bytes);
        buffer_.erase(0, frame.size());
        return std::optional<std::string>(std::move(frame));
      }
    }
  }
  if (!ended_) return std::optional<std::string>();  // stopped or timed out
  return DataLossError("the stream ended inside a PCD file (" + std::to_string(buffer_.size()) +
                       " bytes of it)");
}

}  // namespace relmap::robot
