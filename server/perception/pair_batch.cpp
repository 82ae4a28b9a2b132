// The pair kernel lane by lane. Every expression is the one-pair kernel's with Eigen's
// 4-vector arithmetic spelled out: a dot product of 4-vectors sums (x + z) + (y + w), w = +0
// here, and the cross product is the textbook one. Lanes the fast path cannot decide
// exactly (ties, degenerate pairs, angles near a bin edge) fall back to ComputePairCodes.
#include "perception/pair_batch.h"

#include <algorithm>
#include <cmath>

namespace relmap::perception {
namespace {

// Eigen's Vector4f dot product with w = 0 in both operands.
inline float Dot(float ax, float ay, float az, float bx, float by, float bz) {
  return (ax * bx + az * bz) + (ay * by + 0.0f);
}

// BinOf without std::floor, which SSE2 cannot vectorise: for the finite values met here a
// truncation clamped to [0, 10] gives the same bin (they differ only below 0, clamped).
inline int UnitBin(float f) {
  const int b = static_cast<int>(kFpfhBins * ((f + 1.0) * 0.5));
  return std::clamp(b, 0, kFpfhBins - 1);
}

}  // namespace

void PairBatch::Add(const Eigen::Vector4f& p1, const Eigen::Vector4f& n1, const Eigen::Vector4f& p2,
                    const Eigen::Vector4f& n2, std::size_t tag) {
  for (int a = 0; a < 3; ++a) {
    p1_[a][size_] = p1[a], n1_[a][size_] = n1[a], p2_[a][size_] = p2[a], n2_[a][size_] = n2[a];
  }
  tag_[size_++] = tag;
}

void PairBatch::Compute() {
  namespace in = pair_features_internal;
  // Branch-free (& rather than &&, selects rather than ifs): control flow stops GCC from
  // vectorising the loop.
  alignas(16) int fast[kPairBatch];  // 1: the fast path decided this lane
  alignas(16) PairCode code[kPairBatch];
  const auto half_pi = static_cast<float>(M_PI_2), pi = static_cast<float>(M_PI);
  for (int l = 0; l < size_; ++l) {
    const float dx = p2_[0][l] - p1_[0][l], dy = p2_[1][l] - p1_[1][l], dz = p2_[2][l] - p1_[2][l];
    const float f4 = std::sqrt(Dot(dx, dy, dz, dx, dy, dz));
    const float n1x = n1_[0][l], n1y = n1_[1][l], n1z = n1_[2][l];
    const float n2x = n2_[0][l], n2y = n2_[1][l], n2z = n2_[2][l];
    const float angle1 = Dot(n1x, n1y, n1z, dx, dy, dz) / f4;
    const float angle2 = Dot(n2x, n2y, n2z, dx, dy, dz) / f4;
    // ComputePairCodes' source choice, without its acos fallback (those lanes are redone).
    const float a1 = std::fabs(angle1), a2 = std::fabs(angle2);
    const bool p1_source = a1 > a2 + 1e-6f;
    bool decided = (f4 != 0.0f) & (a1 <= 1.0f) & (a2 <= 1.0f) & (p1_source | (a1 < a2 - 1e-6f));
    const float sign = p1_source ? 1.0f : -1.0f;  // d or -d = d * -1, exact either way
    const float sx = dx * sign, sy = dy * sign, sz = dz * sign;
    const float ux = p1_source ? n1x : n2x, uy = p1_source ? n1y : n2y, uz = p1_source ? n1z : n2z;
    const float tx = p1_source ? n2x : n1x, ty = p1_source ? n2y : n1y, tz = p1_source ? n2z : n1z;
    const float minus_angle2 = -angle2;
    const float f3 = p1_source ? angle1 : minus_angle2;
    // FromSource: v = d × u / |d × u|, w = u × v.
    float vx = sy * uz - sz * uy, vy = sz * ux - sx * uz, vz = sx * uy - sy * ux;
    const float v_norm = std::sqrt(Dot(vx, vy, vz, vx, vy, vz));
    decided &= v_norm != 0.0f;
    vx /= v_norm, vy /= v_norm, vz /= v_norm;
    const float wx = uy * vz - uz * vy, wy = uz * vx - ux * vz, wz = ux * vy - uy * vx;
    const float f2 = Dot(vx, vy, vz, tx, ty, tz);
    const float y = Dot(wx, wy, wz, tx, ty, tz), x = Dot(ux, uy, uz, tx, ty, tz);
    // AngleBin's fast path, also with a truncation for the floor.
    const float ax = std::fabs(x), ay = std::fabs(y);
    const float hi = std::max(ax, ay), lo = std::min(ax, ay);
    decided &= (hi > 0.0f) & (hi <= 1e30f);
    // Every value is computed, then selected: GCC does not if-convert a conditional float
    // operation (it could trap). Undecided lanes are redone; their NaNs must not reach the
    // int conversions below.
    const float atan_t = in::AtanUnit(lo / hi);
    float a = decided ? atan_t : 0.0f;
    const float complement = half_pi - a;
    a = ay > ax ? complement : a;
    const float supplement = pi - a;
    a = x < 0.0f ? supplement : a;
    const float negated = -a;
    a = y < 0.0f ? negated : a;
    const double scaled = kFpfhBins * ((a + M_PI) * in::kInverseTwoPi);
    const int b1 = static_cast<int>(scaled);
    const double fraction = scaled - b1;
    decided &= (scaled >= 0.0) & (fraction > 1e-3) & (fraction < 1.0 - 1e-3);
    code[l] = static_cast<PairCode>(std::min(b1, kFpfhBins - 1) * kFpfhBins * kFpfhBins +
                                    UnitBin(decided ? f2 : 0.0f) * kFpfhBins +
                                    UnitBin(decided ? f3 : 0.0f));
    fast[l] = decided ? 1 : 0;
  }
  for (int l = 0; l < size_; ++l) {
    if (fast[l]) {
      codes_[l] = {code[l], code[l]};
      continue;
    }
    const auto vector = [l](const float(&c)[3][kPairBatch]) {
      return Eigen::Vector4f(c[0][l], c[1][l], c[2][l], 0.0f);
    };
    codes_[l] = ComputePairCodes(vector(p1_), vector(n1_), vector(p2_), vector(n2_));
  }
}

}  // namespace relmap::perception
