// PCL's Darboux-frame pair features (pcl::computePairFeatures) and the FPFH binning of one
// pair, inlined: the innermost loop of the voxel FPFH, where PCL's out-of-line call cost ~20%.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace relmap::perception {

inline constexpr int kFpfhBins = 11;
inline constexpr int kFpfhDims = 3 * kFpfhBins;

// A pair's three FPFH bins packed as b1 * 121 + b2 * 11 + b3.
using PairCode = std::uint16_t;

// The codes of the pair as p1 sees it (p1, n1, p2, n2) and as p2 sees it (p2, n2, p1, n1).
struct PairCodes {
  PairCode forward, backward;
};

namespace pair_features_internal {

// FPFHEstimation::computePointSPFHSignature's binning of one value, same expressions and
// types: the scaled value is a double, the bin floor(11 * scaled) clamped to [0, 10].
inline int BinOf(double scaled) {
  const int b = static_cast<int>(std::floor(kFpfhBins * scaled));
  return b < 0 ? 0 : (b >= kFpfhBins ? kFpfhBins - 1 : b);
}

// PCL scales f1 as (f1 + M_PI) * d_pi_, d_pi_ its float 1/2π.
inline constexpr float kInverseTwoPi = 1.0f / (2.0f * static_cast<float>(M_PI));

inline PairCode Bin(int b1, float f2, float f3) {
  return static_cast<PairCode>(b1 * kFpfhBins * kFpfhBins + BinOf((f2 + 1.0) * 0.5) * kFpfhBins +
                               BinOf((f3 + 1.0) * 0.5));
}

// atan(t) on [0, 1] by a minimax polynomial in t² (NVIDIA Cg's atan2), error < 1e-5 rad
// (checked by pair_features_test).
inline float AtanUnit(float t) {
  const float t2 = t * t;
  float p = -0.013480470f;
  p = p * t2 + 0.057477314f;
  p = p * t2 - 0.121239071f;
  p = p * t2 + 0.195635925f;
  p = p * t2 - 0.332994597f;
  p = p * t2 + 0.999995630f;
  return p * t;
}

// The f1 bin of atan2(y, x) without atan2f where possible: only which of 11 bins the angle
// falls in matters, so an approximation 1e-5 rad off decides every angle more than 1e-3 bin
// widths (5.7e-4 rad) from a bin edge; the rest (~0.2%) take PCL's atan2f path.
inline int AngleBin(float y, float x) {
  const float ax = std::fabs(x), ay = std::fabs(y);
  const float hi = std::max(ax, ay), lo = std::min(ax, ay);
  if (hi > 0.0f && hi <= 1e30f) {
    const auto half_pi = static_cast<float>(M_PI_2);
    const auto pi = static_cast<float>(M_PI);
    float a = AtanUnit(lo / hi);
    if (ay > ax) a = half_pi - a;
    if (x < 0.0f) a = pi - a;
    if (y < 0.0f) a = -a;
    const double scaled = kFpfhBins * ((a + M_PI) * kInverseTwoPi);
    const double below = std::floor(scaled);
    if (scaled - below > 1e-3 && scaled - below < 1.0 - 1e-3) {
      return std::clamp(static_cast<int>(below), 0, kFpfhBins - 1);
    }
  }
  return BinOf((std::atan2(y, x) + M_PI) * kInverseTwoPi);
}

// pcl::computePairFeatures after its choice of source point, with PCL's Eigen 4-vector
// expressions so that every rounding matches: u = source normal, v = d × u / |d × u|,
// w = u × v; f1 = atan2(w·n_t, u·n_t), f2 = v·n_t, f3 = the source's u·d / |d|.
inline PairCode FromSource(const Eigen::Vector4f& d, const Eigen::Vector4f& u,
                           const Eigen::Vector4f& n_t, float f3) {
  Eigen::Vector4f v = d.cross3(u);
  v[3] = 0.0f;
  const float v_norm = v.norm();
  // No Darboux frame: pcl::computePairFeatures fails with f = 0, but FPFHEstimation's
  // wrapper reports success, so PCL's FPFH counts the pair in the middle bins.
  if (v_norm == 0.0f) return Bin(BinOf(M_PI * kInverseTwoPi), 0.0f, 0.0f);
  v /= v_norm;
  Eigen::Vector4f w = u.cross3(v);
  v[3] = 0.0f;
  w[3] = 0.0f;
  return Bin(AngleBin(w.dot(n_t), u.dot(n_t)), v.dot(n_t), f3);
}

}  // namespace pair_features_internal

// Both directions of a pair at once. PCL makes the point whose normal is closer to the
// line p1p2 the source (larger |cos|, i.e. smaller acos(|cos|)), so both directions give
// the same features and cost one computation; only when the two acos tie does each
// direction keep its own first point. Positions and normals have w = 0.
inline PairCodes ComputePairCodes(const Eigen::Vector4f& p1, const Eigen::Vector4f& n1,
                                  const Eigen::Vector4f& p2, const Eigen::Vector4f& n2) {
  namespace in = pair_features_internal;
  const Eigen::Vector4f d = p2 - p1;
  const float f4 = d.norm();
  if (f4 == 0.0f) {  // coincident points: counted with f = 0, as above
    const PairCode middle = in::Bin(in::BinOf(M_PI * in::kInverseTwoPi), 0.0f, 0.0f);
    return {middle, middle};
  }
  const float angle1 = n1.dot(d) / f4;
  const float angle2 = n2.dot(d) / f4;
  // On [0, 1] acos is decreasing with slope magnitude >= 1 and its float results are at
  // most 1.2e-7 apart, so |angle| values more than 1e-6 apart order the acos strictly: PCL's
  // two acosf calls are needed only when they are closer, or when rounding pushed an |angle|
  // above 1 (acosf gives NaN, which compares false both ways, like a tie).
  const float a1 = std::fabs(angle1), a2 = std::fabs(angle2);
  const bool in_domain = a1 <= 1.0f && a2 <= 1.0f;
  int order;  // -1: acos(a1) > acos(a2) (p2 is the source), +1: less, 0: neither
  if (in_domain && a1 < a2 - 1e-6f) {
    order = -1;
  } else if (in_domain && a1 > a2 + 1e-6f) {
    order = 1;
  } else {
    const float c1 = std::acos(a1), c2 = std::acos(a2);
    order = c1 > c2 ? -1 : (c1 < c2 ? 1 : 0);
  }
  const Eigen::Vector4f minus_d = d * -1.0f;
  if (order != 0) {
    // One source for both directions: p1 (order > 0) or p2 (PCL's swap, f3 = -angle2).
    // Selected without a branch: the order of a pair is a coin toss to the predictor.
    const bool p1_source = order > 0;
    const PairCode code = in::FromSource(p1_source ? d : minus_d, p1_source ? n1 : n2,
                                         p1_source ? n2 : n1, p1_source ? angle1 : -angle2);
    return {code, code};
  }
  // Neither: no swap in either direction; seen from p2, its angle1 is n2·(p1 - p2) / |d|.
  return {in::FromSource(d, n1, n2, angle1), in::FromSource(minus_d, n2, n1, -angle2)};
}

}  // namespace relmap::perception
