// Three decimals: the fields are compared by eye and between pipelines, not parsed back.
#include "feature_report.h"

#include <algorithm>
#include <cstdio>

#include "perception/colour_histogram.h"
#include "perception/fpfh.h"
#include "perception/pair_features.h"

namespace relmap::tools {

std::string FpfhDeviationJson(const perception::Frame& frame,
                              const perception::PerceptionConfig& config) {
  // 33 values in 3 blocks summing to 1 each: the L1 distance is at most 6.
  const Eigen::MatrixXd exact =
      perception::SupervoxelFpfhExactUnion(frame.segmentation, config.features.fpfh_radius, 1);
  const Eigen::MatrixXd shared = perception::SupervoxelFpfhSharedVoxels(
      frame.segmentation, config.features.fpfh_radius, config.threads);
  const Eigen::MatrixXd diff = (exact - shared).cwiseAbs();
  const Eigen::VectorXd l1 = diff.rowwise().sum();
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer),
                R"(,"fpfh_l1_mean":%.4f,"fpfh_l1_max":%.4f,"fpfh_abs_max":%.4f)", l1.mean(),
                l1.maxCoeff(), diff.maxCoeff());
  return buffer;
}

std::string FeatureStatsJson(const perception::FeatureMatrix& features) {
  Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(perception::kFeatureDims);
  std::size_t rows = 0;
  for (Eigen::Index r = 0; r < features.values.rows(); ++r) {
    if (features.non_finite[static_cast<std::size_t>(r)] > 0) continue;
    sum += features.values.row(r);
    ++rows;
  }
  const Eigen::RowVectorXd mean = sum / static_cast<double>(std::max<std::size_t>(rows, 1));
  std::string json = ",\"mean_feature\":[";
  char number[32];
  for (int d = 0; d < perception::kFeatureDims; ++d) {
    std::snprintf(number, sizeof(number), "%s%.3f", d ? "," : "", mean[d]);
    json += number;
  }
  json += "],\"fpfh_block_max\":[";
  for (int block = 0; block < 3; ++block) {
    const double peak =
        mean.segment(perception::kColourDims + block * perception::kFpfhBins, perception::kFpfhBins)
            .maxCoeff();
    std::snprintf(number, sizeof(number), "%s%.3f", block ? "," : "", peak);
    json += number;
  }
  return json + "]";
}

}  // namespace relmap::tools
