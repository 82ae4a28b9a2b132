// Assembly of the §2 feature: colour histogram, FPFH, zeroing of tiny values, and the
// count of non-finite values per row.
#include "perception/features.h"

#include <algorithm>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "perception/colour_histogram.h"
#include "perception/fpfh.h"

namespace relmap::perception {

FeatureMatrix ComputeFeatures(const Cloud& cloud, const Segmentation& segmentation,
                              const FeatureConfig& config, int threads) {
#ifdef _OPENMP
  if (threads <= 0) threads = omp_get_max_threads();
#endif
  threads = std::max(threads, 1);
  const std::vector<Supervoxel>& svs = segmentation.supervoxels;
  const auto n = static_cast<Eigen::Index>(svs.size());
  FeatureMatrix f;
  f.values.resize(n, kFeatureDims);
  // Rows are independent; the Lab conversion (pow, cbrt per voxel) is worth two threads.
#pragma omp parallel num_threads(threads)
  {
    std::vector<std::array<std::uint8_t, 3>> colours;
#pragma omp for schedule(dynamic, 16)
    for (Eigen::Index s = 0; s < n; ++s) {
      const Supervoxel& sv = svs[static_cast<std::size_t>(s)];
      colours.clear();
      for (const Voxel& v : sv.voxels) colours.push_back(v.rgb);  // §2: voxel mean colours
      f.values.row(s).head<kColourDims>() = ColourHistogram(colours, config.colour).transpose();
    }
  }
  f.values.rightCols<kFpfhDims>() = SupervoxelFpfh(cloud, segmentation, config, threads);
  f.non_finite.assign(svs.size(), 0);
  for (Eigen::Index s = 0; s < n; ++s) {
    for (Eigen::Index d = 0; d < kFeatureDims; ++d) {
      double& v = f.values(s, d);
      if (!std::isfinite(v)) {
        ++f.non_finite[static_cast<std::size_t>(s)];
      } else if (v < config.zero_below) {
        v = 0.0;  // the authors' code zeroed values < 1e-3 from Feb. 2018 on
      } else if (v > 1.0) {
        v = 1.0;  // float rounding of a histogram fraction; §2 promises [0, 1]
      }
    }
    if (f.non_finite[static_cast<std::size_t>(s)] > 0) ++f.non_finite_rows;
  }
  return f;
}

}  // namespace relmap::perception
