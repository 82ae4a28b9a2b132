// Distance of each candidate to the labelled set, as a share of the frame's median.
#include "exploration/novelty.h"

#include <algorithm>
#include <vector>

namespace relmap::exploration {
namespace {

// The share of the mean variance every dimension keeps, so that a dimension that
// is constant in the labelled samples (8–9 of the 48 in the authors' data) does
// not dominate the distance with a division by ~0. The same floor as the
// covariance prior's φ (§3.10.1).
constexpr double kVarianceFloorShare = 0.01;

// Samples beyond which the labelled set is thinned to its latest ones: the
// distance costs O(candidates × samples × p), and recent samples are the ones
// the exploration risks repeating.
constexpr int kMaxReferenceSamples = 2048;

}  // namespace

Eigen::VectorXd Novelty(const Eigen::Ref<const Eigen::MatrixXd>& candidates,
                        const cmm::Dataset& labelled) {
  const Eigen::Index m = candidates.rows();
  if (labelled.size() < 2 || m == 0) return Eigen::VectorXd::Ones(m);

  const int n = std::min(labelled.size(), kMaxReferenceSamples);
  const Eigen::MatrixXd samples = labelled.features().bottomRows(n);
  const Eigen::RowVectorXd mean = samples.colwise().mean();
  const Eigen::RowVectorXd variance =
      (samples.rowwise() - mean).array().square().colwise().sum() / static_cast<double>(n - 1);
  const double floor = kVarianceFloorShare * variance.mean();
  if (!(floor > 0.0)) return Eigen::VectorXd::Ones(m);  // every labelled sample the same
  const Eigen::RowVectorXd inverse_scale = (variance.array() + floor).rsqrt().matrix();

  // ‖a − b‖² = ‖a‖² + ‖b‖² − 2a·b, in the standardised space, as one product.
  const Eigen::MatrixXd a = candidates.array().rowwise() * inverse_scale.array();
  const Eigen::MatrixXd b = samples.array().rowwise() * inverse_scale.array();
  const Eigen::VectorXd a2 = a.rowwise().squaredNorm();
  const Eigen::RowVectorXd b2 = b.rowwise().squaredNorm().transpose();
  Eigen::MatrixXd d2 = -2.0 * a * b.transpose();
  d2.colwise() += a2;
  d2.rowwise() += b2;
  const Eigen::VectorXd nearest = d2.rowwise().minCoeff().cwiseMax(0.0);

  std::vector<double> sorted(nearest.data(), nearest.data() + m);
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(m / 2);
  std::nth_element(sorted.begin(), middle, sorted.end());
  const double h2 = *middle;
  if (!(h2 > 0.0)) return (nearest.array() > 0.0).cast<double>().matrix();
  return nearest.array() / (nearest.array() + h2);
}

}  // namespace relmap::exploration
