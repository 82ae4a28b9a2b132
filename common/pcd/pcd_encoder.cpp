// The header PCL's own writer produces, then the points as 16-byte records.
#include "common/pcd/pcd_encoder.h"

#include <cstring>

namespace relmap::pcd {

std::string EncodePcd(std::uint32_t width, std::uint32_t height, const std::vector<Point>& points) {
  std::string pcd =
      "# .PCD v0.7 - Point Cloud Data file format (written by relmap)\n"
      "VERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n";
  pcd += "WIDTH " + std::to_string(width) + "\nHEIGHT " + std::to_string(height) +
         "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(points.size()) + "\nDATA binary\n";
  const std::size_t header_bytes = pcd.size();
  pcd.resize(header_bytes + 16 * points.size());
  char* record = pcd.data() + header_bytes;
  for (const Point& p : points) {
    const std::uint32_t rgb = (std::uint32_t{p.r} << 16) | (std::uint32_t{p.g} << 8) | p.b;
    std::memcpy(record, &p.x, 4);
    std::memcpy(record + 4, &p.y, 4);
    std::memcpy(record + 8, &p.z, 4);
    std::memcpy(record + 12, &rgb, 4);  // little endian, as PCD binary data is
    record += 16;
  }
  return pcd;
}

}  // namespace relmap::pcd
