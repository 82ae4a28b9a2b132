// Pooled covariance prior and background density, recomputed from the dataset
// at checkpoints (covariance_prior.h).
#include "cmm/covariance_prior.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "cmm/whitened_distance.h"

namespace relmap::cmm {
namespace {

// B's covariance is the total covariance times this: a standard deviation twice
// that of all the data.
constexpr double kBackgroundInflation = 4.0;

const double kLogTwoPi = std::log(2.0 * std::numbers::pi);

struct Moments {
  Eigen::MatrixXd within_scatter;  // Σ_l Σ_{i∈l} (x_i − x̄_l)(x_i − x̄_l)ᵀ
  Eigen::MatrixXd total_scatter;   // Σ_i (x_i − x̄)(x_i − x̄)ᵀ
  Eigen::VectorXd mean;
  int within_dof = 0;  // count − number of classes present
};

// Two passes (means, then centred scatters): the one-pass formula loses the
// small variances of [0, 1] features to cancellation.
Moments ComputeMoments(const Dataset& data, int count) {
  const int p = data.dimension();
  Moments m;
  Eigen::VectorXd class_sum[2] = {Eigen::VectorXd::Zero(p), Eigen::VectorXd::Zero(p)};
  int class_count[2] = {0, 0};
  for (int i = 0; i < count; ++i) {
    class_sum[data.label(i)] += data.sample(i);
    ++class_count[data.label(i)];
  }
  m.mean = (class_sum[0] + class_sum[1]) / count;
  Eigen::VectorXd class_mean[2];
  for (int l = 0; l < 2; ++l) {
    class_mean[l] = class_count[l] > 0 ? Eigen::VectorXd(class_sum[l] / class_count[l])
                                       : Eigen::VectorXd::Zero(p);
  }
  Eigen::MatrixXd within(p, count);
  Eigen::MatrixXd total(p, count);
  for (int i = 0; i < count; ++i) {
    within.col(i) = data.sample(i) - class_mean[data.label(i)];
    total.col(i) = data.sample(i) - m.mean;
  }
  m.within_scatter.noalias() = within * within.transpose();
  m.total_scatter.noalias() = total * total.transpose();
  m.within_dof = count - (class_count[0] > 0) - (class_count[1] > 0);
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
  const double p = static_cast<double>(s.rows());
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
  int power = 0;
  for (int k = 1; k > 0 && k <= size; k <<= 1) power = k;
  return power;
}

CovariancePrior ComputeCovariancePrior(const Dataset& data, int count, const CmmConfig& config) {
  const int p = data.dimension();
  const Moments moments = ComputeMoments(data, count);
  const double mean_square = moments.mean.squaredNorm() / p;
  const double fallback = mean_square > 0.0 ? mean_square : 1.0;

  CovariancePrior prior;
  prior.computed_from = count;
  prior.pseudo_samples = config.PseudoSamples(p);
  const Eigen::MatrixXd total =
      ShrunkCovariance(moments.total_scatter, count - 1, fallback);
  prior.scale = moments.within_dof > 0 && moments.within_scatter.trace() > 0.0
                    ? ShrunkCovariance(moments.within_scatter, moments.within_dof, fallback)
                    : total;
  prior.floor = config.variance_floor * prior.scale.trace() / p;

  Eigen::MatrixXd background = kBackgroundInflation * total;
  background.diagonal().array() += kBackgroundInflation * prior.floor;
  const Eigen::LLT<Eigen::MatrixXd> cholesky(background);
  const Eigen::MatrixXd lower = cholesky.matrixL();
  prior.background_whitening =
      lower.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(p, p));
  prior.background_log_normaliser =
      -lower.diagonal().array().log().sum() - 0.5 * p * kLogTwoPi;
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
