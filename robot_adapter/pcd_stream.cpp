// Cutting a stream of PCD files into frames.
#include "pcd_stream.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <vector>

namespace relmap::robot {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

std::vector<std::string_view> Words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

bool ToSize(std::string_view word, std::size_t* value) {
  auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), *value);
  return error == std::errc() && end == word.data() + word.size();
}

Status NotPcd(const std::string& what) {
  return InvalidArgumentError("the stream does not hold a PCD file here: " + what);
}

bool IsGap(char c) { return c == '\0' || c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

}  // namespace

StatusOr<std::optional<PcdFraming>> ParsePcdFraming(std::string_view bytes,
                                                    std::size_t max_frame_bytes) {
  PcdFraming framing;
  std::vector<std::size_t> sizes;
  std::vector<std::size_t> counts;
  std::size_t width = 0;
  std::size_t height = 1;
  std::optional<std::size_t> points;
  std::size_t position = 0;
  for (;;) {
    const std::size_t end = bytes.find('\n', position);
    if (end == std::string_view::npos) {
      if (bytes.size() > kMaxHeaderBytes) return NotPcd("no DATA line in the first 64 KiB");
      return std::optional<PcdFraming>();
    }
    const std::vector<std::string_view> words = Words(bytes.substr(position, end - position));
    position = end + 1;
    if (words.empty() || words[0][0] == '#') continue;
    const std::string_view key = words[0];
    const bool numbers =
        key == "SIZE" || key == "COUNT" || key == "WIDTH" || key == "HEIGHT" || key == "POINTS";
    std::vector<std::size_t> values;
    for (std::size_t i = 1; numbers && i < words.size(); ++i) {
      std::size_t value = 0;
      if (!ToSize(words[i], &value)) {
        return NotPcd(std::string(key) + " has \"" + std::string(words[i]) + "\"");
      }
      values.push_back(value);
    }
    if (key == "SIZE") {
      sizes = values;
    } else if (key == "COUNT") {
      counts = values;
    } else if ((key == "WIDTH" || key == "HEIGHT" || key == "POINTS") && values.size() != 1) {
      return NotPcd(std::string(key) + " needs one number");
    } else if (key == "WIDTH") {
      width = values[0];
    } else if (key == "HEIGHT") {
      height = values[0];
    } else if (key == "POINTS") {
      points = values[0];
    } else if (key == "DATA") {
      if (words.size() != 2) return NotPcd("DATA needs one word");
      if (words[1] == "ascii") {
        framing.data = PcdFraming::Data::kAscii;
      } else if (words[1] == "binary") {
        framing.data = PcdFraming::Data::kBinary;
      } else if (words[1] == "binary_compressed") {
        framing.data = PcdFraming::Data::kBinaryCompressed;
      } else {
        return NotPcd("unknown DATA \"" + std::string(words[1]) + "\"");
      }
      break;
    } else if (key != "VERSION" && key != "FIELDS" && key != "TYPE" && key != "VIEWPOINT") {
      return NotPcd("unknown keyword \"" + std::string(key.substr(0, 40)) + "\"");
    }
  }
  framing.header_bytes = position;
  if (counts.empty()) counts.assign(sizes.size(), 1);
  if (sizes.empty() || counts.size() != sizes.size()) {
    return NotPcd("SIZE and COUNT do not describe the same fields");
  }
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (sizes[i] > 8 || counts[i] > 4096) return NotPcd("a field's SIZE or COUNT is too large");
    framing.point_bytes += sizes[i] * counts[i];
  }
  // Every product below stays far from overflow: points is capped before it is used.
  framing.points = points.value_or(width * height);
  if (framing.points > max_frame_bytes || framing.points * framing.point_bytes > max_frame_bytes) {
    return InvalidArgumentError("PCD header declares " + std::to_string(framing.points) +
                                " points, more than a frame's limit of " +
                                std::to_string(max_frame_bytes) + " bytes");
  }
  return std::optional<PcdFraming>(framing);
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
    case PcdFraming::Data::kBinary:
      *bytes = framing.points * framing.point_bytes;
      return true;
    case PcdFraming::Data::kBinaryCompressed: {
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
    case PcdFraming::Data::kAscii:
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
    if (Words(std::string_view(buffer_).substr(position, end - position)).size() > 0) ++lines;
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
