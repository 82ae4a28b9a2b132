// PCD header parsing: every declared number is checked before it sizes anything.
#include "common/pcd/pcd_header.h"

#include <charconv>
#include <set>

namespace relmap::pcd {
namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t{64} * 1024;
constexpr std::size_t kMaxFields = 256;
constexpr int kMaxCount = 4096;  // elements per field: a 4 KiB histogram is already huge

Status HeaderError(int line, const std::string& what) {
  return InvalidArgumentError("PCD header line " + std::to_string(line) + ": " + what);
}

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

template <typename T>
bool ParseNumber(std::string_view s, T& value) {
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

// One keyword line of the header, split into words (the keyword first).
struct HeaderLine {
  int number = 0;
  std::vector<std::string_view> words;
  std::string_view key() const { return words[0]; }
  std::size_t values() const { return words.size() - 1; }
};

// The header's keyword lines in order, up to and including DATA, skipping blank and
// comment lines. Next gives nullopt at the end of `bytes` (no complete line left).
class HeaderLines {
 public:
  explicit HeaderLines(std::string_view bytes) : bytes_(bytes) {}

  StatusOr<std::optional<HeaderLine>> Next() {
    for (;;) {
      if (position_ > kMaxHeaderBytes) return InvalidArgumentError("PCD header longer than 64 KiB");
      const std::size_t eol = bytes_.find('\n', position_);
      if (eol == std::string_view::npos) {
        if (bytes_.size() > kMaxHeaderBytes) {
          return InvalidArgumentError("PCD header longer than 64 KiB");
        }
        return std::optional<HeaderLine>();
      }
      HeaderLine line{++number_, Tokens(bytes_.substr(position_, eol - position_))};
      position_ = eol + 1;
      if (!line.words.empty() && line.key()[0] != '#') return std::optional<HeaderLine>(line);
    }
  }
  // The first byte after the last line given.
  std::size_t position() const { return position_; }

 private:
  std::string_view bytes_;
  std::size_t position_ = 0;
  int number_ = 0;
};

// Reads the keyword lines one by one into a Header, then checks what they declared as a
// whole.
class HeaderReader {
 public:
  explicit HeaderReader(std::uint64_t max_points) : max_points_(max_points) {}

  Status Read(const HeaderLine& line) {
    const std::string_view key = line.key();
    if (key == "VERSION") return OkStatus();
    if (key == "VIEWPOINT") return OkStatus();  // relmap works in the camera frame
    if (key == "FIELDS") return ReadFields(line);
    if (key == "SIZE" || key == "TYPE" || key == "COUNT") return ReadFieldProperty(line);
    if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") return ReadDimension(line);
    if (key == "DATA") return ReadData(line);
    return HeaderError(line.number, "unknown keyword '" + std::string(key.substr(0, 40)) + "'");
  }

  StatusOr<Header> Finish(std::size_t data_offset) {
    header_.data_offset = data_offset;
    if (!have_fields_ || !have_size_ || !have_type_ || !have_width_) {
      return InvalidArgumentError("PCD header misses one of FIELDS, SIZE, TYPE, WIDTH");
    }
    if (!have_height_) header_.height = 1;  // PCD v0.6 files may omit it: unorganized
    const std::uint64_t product = std::uint64_t{header_.width} * header_.height;
    if (product > max_points_) {
      return ResourceExhaustedError("PCD header: WIDTH x HEIGHT = " + std::to_string(product) +
                                    " exceeds the limit of " + std::to_string(max_points_) +
                                    " points");
    }
    if (declared_points_ && *declared_points_ != product) {
      return InvalidArgumentError("PCD header: POINTS " + std::to_string(*declared_points_) +
                                  " differs from WIDTH x HEIGHT = " + std::to_string(product));
    }
    if (product == 0) return InvalidArgumentError("PCD header declares no point");
    header_.points = static_cast<std::size_t>(product);
    for (Field& f : header_.fields) {
      if (f.type == 'F' && f.size != 4 && f.size != 8) {
        return InvalidArgumentError("PCD header: float field '" + f.name + "' has size " +
                                    std::to_string(f.size) + " (expected 4 or 8)");
      }
      f.offset = header_.point_bytes;
      header_.point_bytes += f.bytes();
    }
    return header_;
  }

 private:
  Status ReadFields(const HeaderLine& line) {
    if (line.values() == 0 || line.values() > kMaxFields) {
      return HeaderError(line.number, "FIELDS needs 1 to 256 names");
    }
    std::set<std::string_view> seen;
    for (std::size_t i = 1; i <= line.values(); ++i) {
      if (line.words[i] != "_" && !seen.insert(line.words[i]).second) {
        return HeaderError(line.number,
                           "field '" + std::string(line.words[i]) + "' declared twice");
      }
      header_.fields.push_back(Field{std::string(line.words[i])});
    }
    have_fields_ = true;
    return OkStatus();
  }

  // SIZE, TYPE or COUNT: one value per field.
  Status ReadFieldProperty(const HeaderLine& line) {
    const std::string key(line.key());
    if (!have_fields_) return HeaderError(line.number, key + " before FIELDS");
    if (line.values() != header_.fields.size()) {
      return HeaderError(line.number, key + " has " + std::to_string(line.values()) +
                                          " entries for " + std::to_string(header_.fields.size()) +
                                          " fields");
    }
    for (std::size_t i = 0; i < line.values(); ++i) {
      Field& f = header_.fields[i];
      const std::string_view v = line.words[i + 1];
      if (key == "TYPE") {
        if (v != "F" && v != "I" && v != "U") {
          return HeaderError(line.number, "field '" + f.name + "' has type '" + std::string(v) +
                                              "' (expected F, I or U)");
        }
        f.type = v[0];
        continue;
      }
      int value = 0;
      if (!ParseNumber(v, value)) {
        return HeaderError(line.number, key + " of field '" + f.name + "' is not an integer: '" +
                                            std::string(v) + "'");
      }
      if (key == "SIZE" && value != 1 && value != 2 && value != 4 && value != 8) {
        return HeaderError(line.number, "field '" + f.name + "' has size " + std::to_string(value) +
                                            " (expected 1, 2, 4 or 8)");
      }
      if (key == "COUNT" && (value < 1 || value > kMaxCount)) {
        return HeaderError(line.number, "field '" + f.name + "' has count " +
                                            std::to_string(value) + " (expected 1 to 4096)");
      }
      (key == "SIZE" ? f.size : f.count) = value;
    }
    if (key == "SIZE") have_size_ = true;
    if (key == "TYPE") have_type_ = true;
    return OkStatus();
  }

  // WIDTH, HEIGHT or POINTS: one count, at most max_points.
  Status ReadDimension(const HeaderLine& line) {
    const std::string key(line.key());
    std::uint64_t value = 0;
    if (line.values() != 1 || !ParseNumber(line.words[1], value)) {
      return HeaderError(line.number, key + " needs one non-negative integer");
    }
    if (value > max_points_) {
      return ResourceExhaustedError("PCD header line " + std::to_string(line.number) + ": " + key +
                                    " " + std::to_string(value) + " exceeds the limit of " +
                                    std::to_string(max_points_) + " points");
    }
    if (key == "WIDTH") header_.width = static_cast<std::uint32_t>(value), have_width_ = true;
    if (key == "HEIGHT") header_.height = static_cast<std::uint32_t>(value), have_height_ = true;
    if (key == "POINTS") declared_points_ = value;
    return OkStatus();
  }

  Status ReadData(const HeaderLine& line) {
    const std::string_view kind = line.values() == 1 ? line.words[1] : std::string_view();
    if (kind == "ascii") {
      header_.data = DataKind::kAscii;
    } else if (kind == "binary") {
      header_.data = DataKind::kBinary;
    } else if (kind == "binary_compressed") {
      header_.data = DataKind::kBinaryCompressed;
    } else if (line.values() != 1) {
      return HeaderError(line.number, "DATA needs one of ascii, binary, binary_compressed");
    } else {
      return HeaderError(line.number, "unknown DATA type '" + std::string(kind) + "'");
    }
    return OkStatus();
  }

  const std::uint64_t max_points_;
  Header header_;
  bool have_fields_ = false, have_size_ = false, have_type_ = false;
  bool have_width_ = false, have_height_ = false;
  std::optional<std::uint64_t> declared_points_;
};

// x, y, z as single floats and one 4-byte colour: the fields relmap decodes.
Status CheckPointFields(const Header& h) {
  for (const char* axis : {"x", "y", "z"}) {
    const int i = h.Find(axis);
    if (i < 0) return InvalidArgumentError(std::string("PCD has no field '") + axis + "'");
    const Field& f = h.fields[static_cast<std::size_t>(i)];
    if (f.type != 'F' || f.count != 1) {
      return InvalidArgumentError(std::string("PCD field '") + axis +
                                  "' must be one float (TYPE F, COUNT 1)");
    }
  }
  const int rgb = h.Find("rgb") >= 0 ? h.Find("rgb") : h.Find("rgba");
  if (rgb < 0) return InvalidArgumentError("PCD has no colour field 'rgb' or 'rgba'");
  const Field& c = h.fields[static_cast<std::size_t>(rgb)];
  if (c.size != 4 || c.count != 1) {
    return InvalidArgumentError("PCD colour field '" + c.name +
                                "' must be one 4-byte value (SIZE 4, COUNT 1)");
  }
  return OkStatus();
}

}  // namespace

int Header::Find(std::string_view name) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

StatusOr<std::optional<Header>> ParseHeaderPrefix(std::string_view bytes,
                                                  std::uint64_t max_points) {
  // Each line is checked as it is read, so that what is not PCD is refused at once and
  // not only once a DATA line has come (a stream reader would wait for it forever).
  HeaderLines lines(bytes);
  HeaderReader reader(max_points);
  for (;;) {
    StatusOr<std::optional<HeaderLine>> line = lines.Next();
    if (!line.ok()) return line.status();
    if (!line->has_value()) return std::optional<Header>();
    if (Status read = reader.Read(**line); !read.ok()) return read;
    if ((*line)->key() == "DATA") break;
  }
  StatusOr<Header> header = reader.Finish(lines.position());
  if (!header.ok()) return header.status();
  return std::optional<Header>(std::move(header).value());
}

StatusOr<Header> ParseHeader(std::string_view bytes, std::uint64_t max_points) {
  StatusOr<std::optional<Header>> prefix = ParseHeaderPrefix(bytes, max_points);
  if (!prefix.ok()) return prefix.status();
  if (!prefix->has_value()) {
    return InvalidArgumentError("PCD header ends before its DATA line (file truncated?)");
  }
  if (Status fields = CheckPointFields(**prefix); !fields.ok()) return fields;
  return std::move(**prefix);
}

}  // namespace relmap::pcd
