// PCD header parsing: every declared number is checked before it sizes anything.
#include "perception/pcd_header.h"

#include <charconv>
#include <set>

namespace relmap::perception {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
constexpr int kMaxFields = 256;
constexpr int kMaxCount = 4096;  // elements per field: a 4 KiB histogram is already huge

Status HeaderError(int line, const std::string& what) {
  return InvalidArgumentError("PCD header line " + std::to_string(line) + ": " + what);
}

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
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

}  // namespace

int PcdHeader::Find(std::string_view name) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

StatusOr<PcdHeader> ParsePcdHeader(std::string_view bytes, const DecodeLimits& limits) {
  PcdHeader h;
  std::size_t pos = 0;
  int line_no = 0;
  bool have_fields = false, have_size = false, have_type = false, have_width = false;
  bool have_height = false, have_points = false, have_data = false;
  unsigned long long declared_points = 0;
  while (!have_data) {
    if (pos >= bytes.size()) {
      return InvalidArgumentError("PCD header ends before its DATA line (file truncated?)");
    }
    if (pos > kMaxHeaderBytes) return InvalidArgumentError("PCD header longer than 64 KiB");
    std::size_t eol = bytes.find('\n', pos);
    if (eol == std::string_view::npos) eol = bytes.size();
    std::string_view line = bytes.substr(pos, eol - pos);
    pos = eol + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    std::vector<std::string_view> t = Tokens(line);
    if (t.empty() || t[0][0] == '#') continue;
    const std::string_view key = t[0];
    const std::size_t n = t.size() - 1;
    if (key == "VERSION") {
      continue;
    } else if (key == "FIELDS") {
      if (n == 0 || n > kMaxFields) return HeaderError(line_no, "FIELDS needs 1 to 256 names");
      std::set<std::string_view> seen;
      for (std::size_t i = 1; i <= n; ++i) {
        if (t[i] != "_" && !seen.insert(t[i]).second) {
          return HeaderError(line_no, "field '" + std::string(t[i]) + "' declared twice");
        }
        h.fields.push_back(PcdField{std::string(t[i])});
      }
      have_fields = true;
    } else if (key == "SIZE" || key == "TYPE" || key == "COUNT") {
      if (!have_fields) return HeaderError(line_no, std::string(key) + " before FIELDS");
      if (n != h.fields.size()) {
        return HeaderError(line_no, std::string(key) + " has " + std::to_string(n) +
                                        " entries for " + std::to_string(h.fields.size()) +
                                        " fields");
      }
      for (std::size_t i = 0; i < n; ++i) {
        PcdField& f = h.fields[i];
        const std::string_view v = t[i + 1];
        if (key == "TYPE") {
          if (v != "F" && v != "I" && v != "U") {
            return HeaderError(line_no, "field '" + f.name + "' has type '" + std::string(v) +
                                            "' (expected F, I or U)");
          }
          f.type = v[0];
        } else {
          int value = 0;
          if (!ParseNumber(v, value)) {
            return HeaderError(line_no, std::string(key) + " of field '" + f.name +
                                            "' is not an integer: '" + std::string(v) + "'");
          }
          if (key == "SIZE" && value != 1 && value != 2 && value != 4 && value != 8) {
            return HeaderError(line_no, "field '" + f.name + "' has size " + std::to_string(value) +
                                            " (expected 1, 2, 4 or 8)");
          }
          if (key == "COUNT" && (value < 1 || value > kMaxCount)) {
            return HeaderError(line_no, "field '" + f.name + "' has count " +
                                            std::to_string(value) + " (expected 1 to 4096)");
          }
          (key == "SIZE" ? f.size : f.count) = value;
        }
      }
      if (key == "SIZE") have_size = true;
      if (key == "TYPE") have_type = true;
    } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
      unsigned long long value = 0;
      if (n != 1 || !ParseNumber(t[1], value)) {
        return HeaderError(line_no, std::string(key) + " needs one non-negative integer");
      }
      if (value > static_cast<unsigned long long>(limits.max_points)) {
        return ResourceExhaustedError("PCD header line " + std::to_string(line_no) + ": " +
                                      std::string(key) + " " + std::to_string(value) +
                                      " exceeds the limit of " + std::to_string(limits.max_points) +
                                      " points");
      }
      if (key == "WIDTH") h.width = static_cast<std::uint32_t>(value), have_width = true;
      if (key == "HEIGHT") h.height = static_cast<std::uint32_t>(value), have_height = true;
      if (key == "POINTS") declared_points = value, have_points = true;
    } else if (key == "VIEWPOINT") {
      continue;  // relmap works in the camera frame; a sensor pose is not used
    } else if (key == "DATA") {
      if (n != 1) return HeaderError(line_no, "DATA needs one of ascii, binary, binary_compressed");
      if (t[1] == "ascii") {
        h.data = PcdData::kAscii;
      } else if (t[1] == "binary") {
        h.data = PcdData::kBinary;
      } else if (t[1] == "binary_compressed") {
        h.data = PcdData::kBinaryCompressed;
      } else {
        return HeaderError(line_no, "unknown DATA type '" + std::string(t[1]) + "'");
      }
      have_data = true;
    } else {
      return HeaderError(line_no, "unknown keyword '" + std::string(key) + "'");
    }
  }
  h.data_offset = std::min(pos, bytes.size());
  if (!have_fields || !have_size || !have_type || !have_width) {
    return InvalidArgumentError("PCD header misses one of FIELDS, SIZE, TYPE, WIDTH");
  }
  if (!have_height) h.height = 1;  // PCD v0.6 files may omit it: an unorganized cloud
  const unsigned long long product = static_cast<unsigned long long>(h.width) * h.height;
  if (product > static_cast<unsigned long long>(limits.max_points)) {
    return ResourceExhaustedError("PCD header: WIDTH x HEIGHT = " + std::to_string(product) +
                                  " exceeds the limit of " + std::to_string(limits.max_points) +
                                  " points");
  }
  if (have_points && declared_points != product) {
    return InvalidArgumentError("PCD header: POINTS " + std::to_string(declared_points) +
                                " differs from WIDTH x HEIGHT = " + std::to_string(product));
  }
  if (product == 0) return InvalidArgumentError("PCD header declares no point");
  h.points = static_cast<std::size_t>(product);
  for (PcdField& f : h.fields) {
    if (f.type == 'F' && f.size != 4 && f.size != 8) {
      return InvalidArgumentError("PCD header: float field '" + f.name + "' has size " +
                                  std::to_string(f.size) + " (expected 4 or 8)");
    }
    f.offset = h.point_bytes;
    h.point_bytes += f.bytes();
  }
  for (const char* axis : {"x", "y", "z"}) {
    const int i = h.Find(axis);
    if (i < 0) return InvalidArgumentError(std::string("PCD has no field '") + axis + "'");
    const PcdField& f = h.fields[static_cast<std::size_t>(i)];
    if (f.type != 'F' || f.count != 1) {
      return InvalidArgumentError(std::string("PCD field '") + axis +
                                  "' must be one float (TYPE F, COUNT 1)");
    }
  }
  const int rgb = h.Find("rgb") >= 0 ? h.Find("rgb") : h.Find("rgba");
  if (rgb < 0) return InvalidArgumentError("PCD has no colour field 'rgb' or 'rgba'");
  const PcdField& c = h.fields[static_cast<std::size_t>(rgb)];
  if (c.size != 4 || c.count != 1) {
    return InvalidArgumentError("PCD colour field '" + c.name +
                                "' must be one 4-byte value (SIZE 4, COUNT 1)");
  }
  return h;
}

}  // namespace relmap::perception
