// The prediction and its residuals. Prediction and reconstruction call the same
// functions, so that they round alike on both sides.
#include "perception/compact_cloud.h"

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "perception/word_planes.h"

namespace relmap::perception {
namespace {

std::uint32_t Bits(float v) { return std::bit_cast<std::uint32_t>(v); }
float FromBits(std::uint32_t b) { return std::bit_cast<float>(b); }

// The residual of `actual` against `predicted`, as a small word when they are close.
std::uint32_t Residual(float actual, float predicted) {
  return ZigZag(static_cast<std::int32_t>(Bits(actual) - Bits(predicted)));
}
float Restore(std::uint32_t residual, float predicted) {
  return FromBits(Bits(predicted) + static_cast<std::uint32_t>(UnZigZag(residual)));
}

// What x and y of the point at `index` with depth `z` should be: the pinhole camera's
// (u - cx) z / fx, or the previous finite point's.
struct Predictor {
  std::optional<Intrinsics> intrinsics;
  std::uint32_t width = 1;
  float previous_x = 0, previous_y = 0, previous_z = 0;

  std::pair<float, float> XY(std::size_t index, float z) const {
    if (!intrinsics) return {previous_x, previous_y};
    const std::size_t column = index % width, row = index / width;
    const auto u = static_cast<float>(column);
    const auto v = static_cast<float>(row);
    const auto fx = static_cast<float>(intrinsics->fx), cx = static_cast<float>(intrinsics->cx);
    const auto fy = static_cast<float>(intrinsics->fy), cy = static_cast<float>(intrinsics->cy);
    return {(u - cx) / fx * z, (v - cy) / fy * z};
  }
  void Saw(float x, float y, float z) {
    previous_x = x;
    previous_y = y;
    previous_z = z;
  }
};

}  // namespace

CompactCloud CompactCloud::Of(const Cloud& cloud, bool keep_colour) {
  CompactCloud compact;
  compact.width_ = cloud.width();
  compact.height_ = cloud.height();
  compact.has_colour_ = keep_colour;
  compact.intrinsics_ = IntrinsicsOf(cloud);
  Predictor predictor{compact.intrinsics_, cloud.width()};
  compact.holes_.assign((cloud.size() + 7) / 8, '\0');
  std::vector<std::uint32_t> x, y, z, colours;
  x.reserve(cloud.valid_points());
  y.reserve(cloud.valid_points());
  z.reserve(cloud.valid_points());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const CloudPoint p = cloud.point(i);
    if (!pcd::HasPosition(p)) continue;
    compact.holes_[i / 8] = static_cast<char>(compact.holes_[i / 8] | (1 << (i % 8)));
    const auto [px, py] = predictor.XY(i, p.z);
    x.push_back(Residual(p.x, px));
    y.push_back(Residual(p.y, py));
    z.push_back(Residual(p.z, predictor.previous_z));
    predictor.Saw(p.x, p.y, p.z);
    if (keep_colour) colours.push_back(p.r | (p.g << 8) | (p.b << 16));
  }
  compact.finite_ = z.size();
  x.insert(x.end(), y.begin(), y.end());
  x.insert(x.end(), z.begin(), z.end());
  compact.xyz_ = PackWords(x);
  if (keep_colour) compact.colours_ = PackWords(colours);
  return compact;
}

StatusOr<Cloud> CompactCloud::Expand() const {
  auto xyz = UnpackWords(xyz_, 3 * finite_);
  if (!xyz.ok()) return xyz.status();
  std::vector<std::uint32_t> colours;
  if (has_colour_) {
    auto unpacked = UnpackWords(colours_, finite_);
    if (!unpacked.ok()) return unpacked.status();
    colours = std::move(unpacked).value();
  }
  const std::size_t size = static_cast<std::size_t>(width_) * height_;
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  std::vector<CloudPoint> points(size, CloudPoint{kNan, kNan, kNan, 0, 0, 0, 255});
  Predictor predictor{intrinsics_, width_};
  std::size_t k = 0;
  for (std::size_t i = 0; i < size; ++i) {
    if ((static_cast<unsigned char>(holes_[i / 8]) & (1U << (i % 8))) == 0) continue;
    if (k == finite_) return DataLossError("a compact cloud has more finite points than stored");
    CloudPoint& p = points[i];
    p.z = Restore((*xyz)[2 * finite_ + k], predictor.previous_z);
    const auto [px, py] = predictor.XY(i, p.z);
    p.x = Restore((*xyz)[k], px);
    p.y = Restore((*xyz)[finite_ + k], py);
    predictor.Saw(p.x, p.y, p.z);
    if (has_colour_) {
      p.r = static_cast<std::uint8_t>(colours[k] & 0xffU);
      p.g = static_cast<std::uint8_t>((colours[k] >> 8) & 0xffU);
      p.b = static_cast<std::uint8_t>((colours[k] >> 16) & 0xffU);
    }
    ++k;
  }
  if (k != finite_) return DataLossError("a compact cloud has fewer finite points than stored");
  // The points were a valid cloud already: the decoder's limits were checked on them.
  DecodeLimits limits;
  limits.max_points = static_cast<long long>(size);
  limits.max_abs_coordinate = std::numeric_limits<float>::infinity();
  return MakeCloud(width_, height_, std::move(points), limits);
}

std::size_t CompactCloud::bytes() const {
  return holes_.capacity() + xyz_.capacity() + colours_.capacity();
}

}  // namespace relmap::perception
