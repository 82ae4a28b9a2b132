// CIELab conversions and the colour histogram of §2.
#include "perception/colour_histogram.h"

#include <algorithm>
#include <cmath>

namespace relmap::perception {
namespace {

// sRGB primaries to XYZ (D65), the matrix of the authors' code.
const Eigen::Matrix3d kRgbToXyz = (Eigen::Matrix3d() << 0.4124, 0.3576, 0.1805,  //
                                   0.2126, 0.7152, 0.0722,                       //
                                   0.0193, 0.1192, 0.9505)
                                      .finished();
// D65 white point, with Y = 100.
const Eigen::Vector3d kWhite(95.047, 100.0, 108.883);

double SrgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

int Bin(double value, double lo, double hi) {
  // Equal-width bins over [lo, hi]; the upper bound goes to the last bin (§2).
  const int bin = static_cast<int>(std::floor((value - lo) / (hi - lo) * kColourBins));
  return std::clamp(bin, 0, kColourBins - 1);
}

}  // namespace

Eigen::Vector3d RgbToLab(std::array<std::uint8_t, 3> rgb, ColourConversion conversion) {
  const bool paper = conversion == ColourConversion::kPaper2018;
  Eigen::Vector3d c(rgb[0], rgb[1], rgb[2]);
  if (!paper) {
    // True CIELab: r, g, b in [0, 1], linearised, XYZ scaled so that white has Y = 100.
    for (int i = 0; i < 3; ++i) c[i] = 100.0 * SrgbToLinear(c[i] / 255.0);
  }
  const Eigen::Vector3d t = (kRgbToXyz * c).cwiseQuotient(kWhite);
  // The authors' constant 0.138 against the exact 16/116 = 0.137931.
  const double offset = paper ? 0.138 : 16.0 / 116.0;
  Eigen::Vector3d f;
  for (int i = 0; i < 3; ++i) {
    f[i] = t[i] > 0.008856 ? std::cbrt(t[i]) : 7.787 * t[i] + offset;
  }
  Eigen::Vector3d lab(116.0 * f[1] - 16.0, 500.0 * (f[0] - f[1]), 200.0 * (f[1] - f[2]));
  if (paper) {
    lab[0] = std::min(lab[0], 100.0);
    lab[1] = std::clamp(lab[1], -300.0, 300.0);
    lab[2] = std::clamp(lab[2], -300.0, 300.0);
  }
  return lab;
}

Eigen::Matrix<double, kColourDims, 1> ColourHistogram(
    const std::vector<std::array<std::uint8_t, 3>>& colours, ColourConversion conversion) {
  Eigen::Matrix<double, kColourDims, 1> h = Eigen::Matrix<double, kColourDims, 1>::Zero();
  if (colours.empty()) return h;
  for (const auto& rgb : colours) {
    const Eigen::Vector3d lab = RgbToLab(rgb, conversion);
    h[Bin(lab[0] / 100.0, 0.0, 1.0)] += 1.0;
    h[kColourBins + Bin(lab[1] / 300.0, -1.0, 1.0)] += 1.0;
    h[2 * kColourBins + Bin(lab[2] / 300.0, -1.0, 1.0)] += 1.0;
  }
  return h / static_cast<double>(colours.size());
}

}  // namespace relmap::perception
