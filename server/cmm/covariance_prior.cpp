// Pooled covariance prior and background density, recomputed from the dataset
// at checkpoints (covariance_prior.h).
#include "cmm/covariance_prior.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "cmm/log_math.h"
#include "cmm/whitened_distance.h"

namespace relmap::cmm {
namespace {

// B's covariance is the total covariance times this: a standard deviation twice
// that of all the data.
constexpr double kBackgroundInflation = 4.0;

// The local scatter is estimated from at most this many samples (the first
// ones): it is a scale, and its cost grows with the square of the count.
constexpr int kLocalScatterSamples = 2048;

struct Moments {
  // Σ_i (x_i − x_nn(i))(x_i − x_nn(i))ᵀ over pairs of nearest neighbours of one
  // class: E = 2Σ_local for a smooth density, whatever the spread between
  // clusters.
  Eigen::MatrixXd neighbour_scatter;
  int neighbour_pairs = 0;
  Eigen::MatrixXd total_scatter;  // Σ_i (x_i − x̄)(x_i − x̄)ᵀ
  Eigen::VectorXd mean;
};

// Every sample's nearest neighbour of its own class among the first `count`
// samples (−1 when it is alone in its class), by brute force: O(count²·p).
std::vector<int> SameClassNearestNeighbours(const Dataset& data, int count) {
  std::vector<int> nearest(count, -1);
  std::vector<double> best(count, std::numeric_limits<double>::infinity());
  for (int i = 0; i < count; ++i) {
    for (int j = i + 1; j < count; ++j) {
      if (data.label(i) != data.label(j)) continue;
      const double d = (data.sample(i) - data.sample(j)).squaredNorm();
      if (d < best[i]) best[i] = d, nearest[i] = j;
      if (d < best[j]) best[j] = d, nearest[j] = i;
    }
  }
  return nearest;
}

// Two passes (mean, then centred scatter): the one-pass formula loses the
// small variances of [0, 1] features to cancellation.
Moments ComputeMoments(const Dataset& data, int count) {
  const int p = data.dimension();
  Moments m;
  m.mean = Eigen::VectorXd::Zero(p);
  for (int i = 0; i < count; ++i) m.mean += data.sample(i);
  m.mean /= count;
  Eigen::MatrixXd total(p, count);
  for (int i = 0; i < count; ++i) total.col(i) = data.sample(i) - m.mean;
  m.total_scatter.noalias() = total * total.transpose();

  const int local = std::min(count, kLocalScatterSamples);
  const std::vector<int> nearest = SameClassNearestNeighbours(data, local);
  Eigen::MatrixXd differences(p, local);
  for (int i = 0; i < local; ++i) {
    if (nearest[i] >= 0)
      differences.col(m.neighbour_pairs++) = data.sample(i) - data.sample(nearest[i]);
  }
  const auto used = differences.leftCols(m.neighbour_pairs);
  m.neighbour_scatter.noalias() = used * used.transpose();
  return m;
}

// A covariance from a scatter of `dof` degrees of freedom, shrunk by OAS; the
// fallback when it has no spread at all.
Eigen::MatrixXd ShrunkCovariance(const Eigen::MatrixXd& scatter, int dof, double fallback) {
  const int p = static_cast<int>(scatter.rows());
  if (dof > 0 && scatter.trace() > 0.0) {
    return OracleApproximatingShrinkage(scatter / dof, dof);
  }
  return Eigen::MatrixXd::Identity(p, p) * fallback;
}

}  // namespace

Eigen::MatrixXd OracleApproximatingShrinkage(const Eigen::MatrixXd& s, double n) {
  const auto p = static_cast<double>(s.rows());
  const double trace = s.trace();
  const double trace_of_square = s.squaredNorm();  // tr(s²) = ‖s‖²_F for symmetric s
  const double numerator = (1.0 - 2.0 / p) * trace_of_square + trace * trace;
  const double denominator = (n + 1.0 - 2.0 / p) * (trace_of_square - trace * trace / p);
  const double rho = denominator > 0.0 ? std::min(1.0, numerator / denominator) : 1.0;
  Eigen::MatrixXd shrunk = (1.0 - rho) * s;
  shrunk.diagonal().array() += rho * trace / p;
  return shrunk;
}

int PriorSampleCount(int size) {
  // 64-bit, so that doubling past 2^30 cannot overflow.
  std::int64_t power = 0;
  for (std::int64_t k = 1; k <= size; k <<= 1) power = k;
  return static_cast<int>(power);
}

CovariancePrior ComputeCovariancePrior(const Dataset& data, int count, const CmmConfig& config) {
  const int p = data.dimension();
  const Moments moments = ComputeMoments(data, count);
  const double mean_square = moments.mean.squaredNorm() / p;
  const double fallback = mean_square > 0.0 ? mean_square : 1.0;

  CovariancePrior prior;
  prior.computed_from = count;
  prior.pseudo_samples = config.PseudoSamples(p);
  const Eigen::MatrixXd total = ShrunkCovariance(moments.total_scatter, count - 1, fallback);
  // Σ_local = E[ddᵀ]/2 over the neighbour differences d.
  prior.scale =
      moments.neighbour_pairs > 0 && moments.neighbour_scatter.trace() > 0.0
          ? ShrunkCovariance(moments.neighbour_scatter / 2.0, moments.neighbour_pairs, fallback)
          : total;
  prior.floor = config.variance_floor * prior.scale.trace() / p;

  Eigen::MatrixXd background = kBackgroundInflation * total;
  background.diagonal().array() += kBackgroundInflation * prior.floor;
  const Eigen::LLT<Eigen::MatrixXd> cholesky(background);
  const Eigen::MatrixXd lower = cholesky.matrixL();
  prior.background_whitening =
      lower.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(p, p));
  prior.background_log_normaliser = -lower.diagonal().array().log().sum() - 0.5 * p * kLogTwoPi;
  prior.background_mean = moments.mean;
  return prior;
}

void CovariancePrior::BackgroundLogDensity(const double* points, int count, int stride,
                                           double* out) const {
  const int p = static_cast<int>(background_mean.size());
  const WhiteningView view{background_whitening.data(), p, p, true, background_mean.data()};
  SquaredWhitenedDistances(view, points, count, stride, out);
  for (int i = 0; i < count; ++i) out[i] = background_log_normaliser - 0.5 * out[i];
}

}  // namespace relmap::cmm
