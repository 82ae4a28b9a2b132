// PCD bodies to points. The header is validated first (pcd_header.cpp); here every read
// is checked against the bytes actually present.
#include "common/pcd/pcd_reader.h"

#include <charconv>
#include <cstring>
#include <fstream>
#include <limits>

#include "common/pcd/lzf.h"
#include "common/pcd/pcd_header.h"

namespace relmap::pcd {
namespace {

// Where the x, y, z and colour values of point i start, for either binary layout.
struct FieldReader {
  const char* base;
  std::size_t offset;  // of point 0
  std::size_t stride;  // between points
  const char* at(std::size_t i) const { return base + offset + i * stride; }
};

float ReadCoordinate(const char* p, int size) {
  if (size == 8) {
    double d;
    std::memcpy(&d, p, 8);
    return static_cast<float>(d);
  }
  float f;
  std::memcpy(&f, p, 4);
  return f;
}

void SetColour(std::uint32_t packed, bool has_alpha, Point& point) {
  point.r = static_cast<std::uint8_t>((packed >> 16) & 0xff);
  point.g = static_cast<std::uint8_t>((packed >> 8) & 0xff);
  point.b = static_cast<std::uint8_t>(packed & 0xff);
  point.a = has_alpha ? static_cast<std::uint8_t>(packed >> 24) : 255;
}

StatusOr<std::vector<Point>> DecodeBinaryBody(const Header& h, const char* data, bool field_major) {
  const Field* xyz[3] = {&h.fields[static_cast<std::size_t>(h.Find("x"))],
                         &h.fields[static_cast<std::size_t>(h.Find("y"))],
                         &h.fields[static_cast<std::size_t>(h.Find("z"))]};
  const bool has_rgb = h.Find("rgb") >= 0;
  const Field& colour = h.fields[static_cast<std::size_t>(h.Find(has_rgb ? "rgb" : "rgba"))];
  // binary: point-major (AoS); binary_compressed: field-major (SoA), each field's column of
  // `points` values one after the other.
  auto reader = [&](const Field& f) {
    return field_major ? FieldReader{data, f.offset * h.points, f.bytes()}
                       : FieldReader{data, f.offset, h.point_bytes};
  };
  const FieldReader rx = reader(*xyz[0]), ry = reader(*xyz[1]), rz = reader(*xyz[2]);
  const FieldReader rc = reader(colour);
  std::vector<Point> points(h.points);
  for (std::size_t i = 0; i < h.points; ++i) {
    Point& p = points[i];
    p.x = ReadCoordinate(rx.at(i), xyz[0]->size);
    p.y = ReadCoordinate(ry.at(i), xyz[1]->size);
    p.z = ReadCoordinate(rz.at(i), xyz[2]->size);
    std::uint32_t packed;
    std::memcpy(&packed, rc.at(i), 4);
    SetColour(packed, !has_rgb, p);
  }
  return points;
}

template <typename T>
bool ParseToken(std::string_view s, T& value) {
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

// A float token: also accepts nan/inf spellings (from_chars does) and a leading '+'.
bool ParseFloatToken(std::string_view s, double& value) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  return ParseToken(s, value);
}

StatusOr<std::vector<Point>> DecodeAsciiBody(const Header& h, std::string_view body) {
  std::size_t values_per_point = 0;
  for (const Field& f : h.fields) values_per_point += static_cast<std::size_t>(f.count);
  // Column of the first element of each field.
  std::vector<std::size_t> column(h.fields.size());
  for (std::size_t i = 1; i < h.fields.size(); ++i) {
    column[i] = column[i - 1] + static_cast<std::size_t>(h.fields[i - 1].count);
  }
  const std::size_t cx = column[static_cast<std::size_t>(h.Find("x"))];
  const std::size_t cy = column[static_cast<std::size_t>(h.Find("y"))];
  const std::size_t cz = column[static_cast<std::size_t>(h.Find("z"))];
  const bool has_rgb = h.Find("rgb") >= 0;
  const int colour_index = h.Find(has_rgb ? "rgb" : "rgba");
  const Field& colour = h.fields[static_cast<std::size_t>(colour_index)];
  const std::size_t cc = column[static_cast<std::size_t>(colour_index)];

  std::vector<Point> points;
  points.reserve(h.points);
  std::vector<std::string_view> tokens;
  tokens.reserve(values_per_point);
  std::size_t pos = 0;
  while (points.size() < h.points) {
    if (pos >= body.size()) {
      return InvalidArgumentError("PCD ascii data has " + std::to_string(points.size()) +
                                  " points, the header declares " + std::to_string(h.points));
    }
    std::size_t eol = body.find('\n', pos);
    if (eol == std::string_view::npos) eol = body.size();
    const std::string_view line = body.substr(pos, eol - pos);
    pos = eol + 1;
    tokens.clear();
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      std::size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
      if (j > i) {
        if (tokens.size() == values_per_point) break;  // too many: reported below
        tokens.push_back(line.substr(i, j - i));
      }
      i = j;
    }
    if (tokens.empty()) continue;
    const std::string where = "PCD ascii point " + std::to_string(points.size());
    if (tokens.size() != values_per_point || i < line.size()) {
      return InvalidArgumentError(where + ": expected " + std::to_string(values_per_point) +
                                  " values on its line");
    }
    Point p;
    double v[3];
    const std::size_t cols[3] = {cx, cy, cz};
    for (int a = 0; a < 3; ++a) {
      if (!ParseFloatToken(tokens[cols[a]], v[a])) {
        return InvalidArgumentError(where + ": '" + std::string(tokens[cols[a]]) +
                                    "' is not a number");
      }
    }
    p.x = static_cast<float>(v[0]);
    p.y = static_cast<float>(v[1]);
    p.z = static_cast<float>(v[2]);
    std::uint32_t packed = 0;
    if (colour.type == 'F') {
      // PCL writes a packed rgb as the float with the same bits.
      double d;
      if (!ParseFloatToken(tokens[cc], d)) {
        return InvalidArgumentError(where + ": colour '" + std::string(tokens[cc]) +
                                    "' is not a number");
      }
      const auto f = static_cast<float>(d);
      std::memcpy(&packed, &f, 4);
    } else {
      long long value = 0;
      if (!ParseToken(tokens[cc], value) || value < std::numeric_limits<std::int32_t>::min() ||
          value > std::numeric_limits<std::uint32_t>::max()) {
        return InvalidArgumentError(where + ": colour '" + std::string(tokens[cc]) +
                                    "' is not a 32-bit integer");
      }
      packed = static_cast<std::uint32_t>(value);
    }
    SetColour(packed, !has_rgb, p);
    points.push_back(p);
  }
  return points;
}

StatusOr<std::vector<Point>> DecodeCompressedBody(const Header& h, std::string_view body,
                                                  std::size_t need) {
  std::uint32_t sizes[2];
  if (body.size() < sizeof(sizes)) {
    return InvalidArgumentError("PCD binary_compressed data truncated: no size words");
  }
  std::memcpy(sizes, body.data(), sizeof(sizes));
  const std::uint32_t compressed = sizes[0], uncompressed = sizes[1];
  if (uncompressed != need) {
    return InvalidArgumentError("PCD binary_compressed: uncompressed size " +
                                std::to_string(uncompressed) + " differs from the " +
                                std::to_string(need) + " bytes the header declares");
  }
  if (compressed > body.size() - sizeof(sizes)) {
    return InvalidArgumentError(
        "PCD binary_compressed data truncated: " + std::to_string(compressed) +
        " compressed bytes declared, " + std::to_string(body.size() - sizeof(sizes)) + " present");
  }
  std::vector<char> raw(need);
  const std::size_t got = LzfDecompress(body.substr(sizeof(sizes), compressed), raw.data(), need);
  if (got != uncompressed) {
    return InvalidArgumentError("PCD binary_compressed: corrupt LZF data (decompressed " +
                                std::to_string(got) + " of " + std::to_string(uncompressed) +
                                " bytes)");
  }
  return DecodeBinaryBody(h, raw.data(), /*field_major=*/true);
}

}  // namespace

StatusOr<Points> ReadPcd(std::string_view bytes, const ReadLimits& limits) {
  if (bytes.size() > limits.max_bytes) {
    return InvalidArgumentError("PCD of " + std::to_string(bytes.size()) +
                                " bytes exceeds the limit of " + std::to_string(limits.max_bytes));
  }
  StatusOr<Header> parsed = ParseHeader(bytes, limits.max_points);
  if (!parsed.ok()) return parsed.status();
  const Header& h = *parsed;
  const std::string_view body = bytes.substr(h.data_offset);
  // No overflow: points <= max_points (~1e6) and point_bytes <= 256 fields x 4096 x 8.
  const std::size_t need = h.points * h.point_bytes;
  if (need > limits.max_bytes) {
    return InvalidArgumentError("PCD declares " + std::to_string(need) +
                                " bytes of point data, more than the limit of " +
                                std::to_string(limits.max_bytes));
  }
  StatusOr<std::vector<Point>> points = std::vector<Point>{};
  switch (h.data) {
    case DataKind::kAscii:
      points = DecodeAsciiBody(h, body);
      break;
    case DataKind::kBinary:
      if (body.size() < need) {
        return InvalidArgumentError("PCD binary data truncated: " + std::to_string(h.points) +
                                    " points of " + std::to_string(h.point_bytes) + " bytes need " +
                                    std::to_string(need) + " bytes, got " +
                                    std::to_string(body.size()));
      }
      points = DecodeBinaryBody(h, body.data(), /*field_major=*/false);
      break;
    case DataKind::kBinaryCompressed:
      points = DecodeCompressedBody(h, body, need);
      break;
  }
  if (!points.ok()) return points.status();
  return Points{h.width, h.height, std::move(points).value()};
}

StatusOr<std::string> ReadFileBytes(const std::string& path, std::uint64_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFoundError("cannot open '" + path + "'");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) return InvalidArgumentError("cannot read '" + path + "'");
  if (static_cast<std::uint64_t>(size) > max_bytes) {
    return InvalidArgumentError("'" + path + "' has " + std::to_string(size) +
                                " bytes, more than the limit of " + std::to_string(max_bytes));
  }
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(bytes.data(), size);
  if (!in) return InvalidArgumentError("cannot read '" + path + "'");
  return bytes;
}

}  // namespace relmap::pcd
