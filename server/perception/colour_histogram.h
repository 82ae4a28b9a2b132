// The 15 colour values of a supervoxel's feature (docs/method.md §2): 5-bin histograms of
// CIELab L, a, b over its voxels' mean colours, in either colour conversion.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "perception/perception_config.h"

namespace relmap::perception {

inline constexpr int kColourBins = 5;
inline constexpr int kColourDims = 3 * kColourBins;

// (L, a, b) of an 8-bit sRGB colour; `kPaper2018` reproduces the authors' conversion
// (no gamma linearisation, 0-255 inputs, L clipped at 100, a and b at ±300).
Eigen::Vector3d RgbToLab(std::array<std::uint8_t, 3> rgb, ColourConversion conversion);

// The histogram of (L/100, a/300, b/300) over `colours`: bins of equal width over [0, 1]
// for L and [-1, 1] for a and b, counts divided by the number of colours; layout L bins,
// a bins, b bins. All zero when `colours` is empty.
Eigen::Matrix<double, kColourDims, 1> ColourHistogram(
    const std::vector<std::array<std::uint8_t, 3>>& colours, ColourConversion conversion);

}  // namespace relmap::perception
