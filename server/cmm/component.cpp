// Running statistics and cached factors of one component (§3.1, §3.2).
#include "cmm/component.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "cmm/log_math.h"
#include "cmm/whitened_distance.h"

namespace relmap::cmm {
namespace {

// Thresholds of the authors' density (§3.2, pseudo_density).
constexpr double kPseudoInverseCutoff = 1e-4;  // singular values kept in pinv(Σ) and pdet(2πΣ)
constexpr double kHitRadiusSquared = 1e-4;  // ‖x − μ‖² inside which a kHit component fires
constexpr double kHitScatterSquaredNorm = 1e-4;
constexpr int kHitMaxSize = 4;
// Samples per block of a scatter computed from scratch: a p×64 block (24 KB at
// p = 48) stays on the stack of Eigen's product and in the cache.
constexpr std::size_t kScatterChunk = 64;

}  // namespace

Component::Component(int label, int dimension)
    : label_(label),
      mean_(Eigen::VectorXd::Zero(dimension)),
      scatter_(Eigen::MatrixXd::Zero(dimension, dimension)) {}

Component Component::FromSamples(int label, std::span<const int> indices, const Dataset& data,
                                 const CmmConfig& config, const CovariancePrior* prior) {
  assert(!indices.empty());
  Component c(label, data.dimension());
  c.indices_.assign(indices.begin(), indices.end());
  for (const int i : indices) c.mean_ += data.sample(i);
  c.mean_ /= static_cast<double>(indices.size());
  // The centred scatter a chunk of samples at a time: one p×m copy per call made
  // the allocator map and fault fresh pages for every split proposal (with the
  // 1-NN search, most of an update on random 48-d data at n = 2000).
  Eigen::MatrixXd chunk(data.dimension(), std::min<Eigen::Index>(kScatterChunk, c.size()));
  for (std::size_t first = 0; first < indices.size(); first += kScatterChunk) {
    const auto count = static_cast<Eigen::Index>(std::min(kScatterChunk, indices.size() - first));
    for (Eigen::Index j = 0; j < count; ++j) {
      chunk.col(j) = data.sample(indices[first + static_cast<std::size_t>(j)]) - c.mean_;
    }
    c.scatter_.noalias() += chunk.leftCols(count) * chunk.leftCols(count).transpose();
  }
  c.Refresh(data, config, prior);
  return c;
}

Component Component::FromState(int label, std::vector<int> indices, Eigen::VectorXd mean,
                               Eigen::MatrixXd scatter, double weight, const Dataset& data,
                               const CmmConfig& config, const CovariancePrior* prior) {
  Component c(label, data.dimension());
  c.indices_ = std::move(indices);
  c.mean_ = std::move(mean);
  c.scatter_ = std::move(scatter);
  c.weight_ = weight;
  c.Refresh(data, config, prior);
  return c;
}

Component Component::Union(const Component& a, const Component& b, const Dataset& data,
                           const CmmConfig& config, const CovariancePrior* prior) {
  assert(a.label_ == b.label_);
  Component c(a.label_, data.dimension());
  c.indices_ = a.indices_;
  c.indices_.insert(c.indices_.end(), b.indices_.begin(), b.indices_.end());
  // Chan et al.'s pairwise update of mean and centred scatter.
  const double na = a.size();
  const double nb = b.size();
  const Eigen::VectorXd delta = b.mean_ - a.mean_;
  c.mean_ = a.mean_ + delta * (nb / (na + nb));
  c.scatter_ = a.scatter_ + b.scatter_;
  c.scatter_.noalias() += (na * nb / (na + nb)) * delta * delta.transpose();
  c.Refresh(data, config, prior);
  return c;
}

void Component::AddSample(int index, const Dataset& data, const CmmConfig& config,
                          const CovariancePrior* prior) {
  // Welford: with δ = x − μ_old, μ_new = μ_old + δ/(m+1) and
  // M2_new = M2_old + (m/(m+1)) δδᵀ.
  const double m = size();
  const Eigen::VectorXd delta = data.sample(index) - mean_;
  mean_ += delta / (m + 1.0);
  scatter_.noalias() += (m / (m + 1.0)) * delta * delta.transpose();
  if (!nearest_.nearest.empty()) AddToNearestNeighbours(index, data);
  indices_.push_back(index);
  // Under the same prior a half depends on its samples alone, so halves
  // proposed before any number of appended samples stay valid.
  std::vector<Component> earlier =
      split_ && !split_->empty() ? std::move(*split_) : std::move(earlier_halves_);
  Refresh(data, config, prior);
  earlier_halves_ = std::move(earlier);
}

void Component::Refit(const Dataset& data, const CmmConfig& config, const CovariancePrior* prior) {
  Refresh(data, config, prior);
}

void Component::AddToNearestNeighbours(int index, const Dataset& data) {
  // The new sample has the highest position: strict comparisons keep older
  // neighbours on ties, as the from-scratch search (ties to the lower index) does.
  const int p = data.dimension();
  const int position = size();
  const double* x = data.data() + index;
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int j = 0; j < position; ++j) {
    const double d = SquaredDistance(data.data() + indices_[j], data.stride(), x, data.stride(), p);
    if (d < nearest_.squared_distance[j]) {
      nearest_.squared_distance[j] = d;
      nearest_.nearest[j] = position;
    }
    if (d < best_distance) best_distance = d, best = j;
  }
  nearest_.nearest.push_back(best);
  nearest_.squared_distance.push_back(best_distance);
}

const NearestNeighbourGraph& Component::NearestNeighbours(const Dataset& data) {
  if (nearest_.nearest.size() != indices_.size()) {
    Eigen::MatrixXd points(data.dimension(), size());
    for (int j = 0; j < size(); ++j) points.col(j) = data.sample(indices_[j]);
    nearest_ = cmm::NearestNeighbours(points);
  }
  return nearest_;
}

void Component::Refresh(const Dataset& data, const CmmConfig& config,
                        const CovariancePrior* prior) {
  const int p = data.dimension();
  const int m = size();
  const auto& switches = config.switches;
  log_density_column_.clear();
  split_.reset();
  earlier_halves_.clear();
  unions_.clear();
  // Unique across models and threads: a cached union is looked up by it.
  static std::atomic<std::uint64_t> next_version{1};
  version_ = next_version.fetch_add(1, std::memory_order_relaxed);
  pseudo_samples_ = 0.0;
  centre_ = (switches.first_sample_mean && m <= kHitMaxSize)
                ? Eigen::VectorXd(data.sample(indices_[0]))
                : mean_;
  whitening_is_lower_triangular_ = true;

  if (switches.pseudo_density) {
    if (m <= kHitMaxSize || scatter_.squaredNorm() < kHitScatterSquaredNorm) {
      shape_ = Shape::kHit;
      whitening_.setIdentity(p, p);
      log_normaliser_ = m <= kHitMaxSize ? 0.0 : -p * kLogTwoPi;  // peak 1 or (2π)^−p
      return;
    }
    // The authors' density: exp(−d²/2) / pdet(2πΣ), d² with pinv(Σ). Σ is
    // symmetric positive semi-definite, so its singular values are the absolute
    // eigenvalues and its SVD is its eigendecomposition.
    const Eigen::MatrixXd sigma = scatter_ / (m - 1.0);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(sigma);
    const Eigen::VectorXd singular = eigen.eigenvalues().cwiseAbs();
    int kept = 0;
    for (int i = 0; i < p; ++i) kept += singular[i] > kPseudoInverseCutoff ? 1 : 0;
    whitening_.resize(kept, p);
    log_normaliser_ = 0.0;
    for (int i = 0, row = 0; i < p; ++i) {
      if (singular[i] > kPseudoInverseCutoff) {
        whitening_.row(row++) = eigen.eigenvectors().col(i).transpose() / std::sqrt(singular[i]);
      }
      const double scaled = 2.0 * std::numbers::pi * singular[i];
      if (scaled > kPseudoInverseCutoff) log_normaliser_ -= std::log(scaled);
    }
    shape_ = Shape::kGaussian;
    whitening_is_lower_triangular_ = false;
    return;
  }

  Eigen::MatrixXd sigma;
  if (config.covariance == CovarianceEstimate::kPooledPrior) {
    assert(prior != nullptr && prior->computed_from > 0);
    // MAP under the inverse-Wishart prior of κ pseudo-samples of Ψ, plus the
    // floor: positive definite for every m >= 1, one sample included.
    pseudo_samples_ = prior->pseudo_samples;
    sigma = (scatter_ + pseudo_samples_ * prior->scale) / (m + pseudo_samples_);
    sigma.diagonal().array() += prior->floor;
  } else if (m < 2) {
    shape_ = Shape::kUnit;
    whitening_.setIdentity(p, p);
    log_normaliser_ = -0.5 * p * kLogTwoPi;
    return;
  } else {
    // Σ̃ = Σ + λI with Σ the unbiased covariance; λ > 0 keeps Σ̃ positive
    // definite even for m <= p or duplicate samples.
    sigma = scatter_ / (m - 1.0);
    sigma.diagonal().array() += config.regularization;
  }
  const Eigen::LLT<Eigen::MatrixXd> cholesky(sigma);
  const Eigen::MatrixXd lower = cholesky.matrixL();
  whitening_ = lower.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(p, p));
  // log G = −½ d² − Σ log L_ii − (p/2) log 2π: the log domain avoids the
  // underflow of a product of 48 Gaussian factors.
  log_normaliser_ = -lower.diagonal().array().log().sum() - 0.5 * p * kLogTwoPi;
  if (pseudo_samples_ > 0.0 && m >= 2) {
    leave_one_out_log_normaliser_ =
        log_normaliser_ - 0.5 * p * std::log((m + pseudo_samples_) / (m - 1.0 + pseudo_samples_));
  }
  shape_ = Shape::kGaussian;
}

double Component::SquaredMahalanobis(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  double out = 0.0;
  const Eigen::VectorXd contiguous = x;
  SquaredMahalanobis(contiguous.data(), 1, 1, &out);
  return out;
}

void Component::SquaredMahalanobis(const double* points, int count, int stride, double* out) const {
  const WhiteningView view{whitening_.data(), static_cast<int>(whitening_.rows()),
                           static_cast<int>(mean_.size()), whitening_is_lower_triangular_,
                           centre_.data()};
  SquaredWhitenedDistances(view, points, count, stride, out);
}

double Component::LogDensityFromSquaredDistance(double squared_distance) const {
  if (shape_ == Shape::kHit) {
    return squared_distance < kHitRadiusSquared ? log_normaliser_
                                                : -std::numeric_limits<double>::infinity();
  }
  return log_normaliser_ - 0.5 * squared_distance;
}

double Component::LeaveOneOutLogDensity(double log_density) const {
  assert(pseudo_samples_ > 0.0);
  const double m = size();
  if (m < 2.0) return -std::numeric_limits<double>::infinity();
  const double kappa = pseudo_samples_;
  const double a = m / (m - 1.0);
  const double q = SquaredDistanceFromLogDensity(log_density) / (m + kappa);
  // aq < 1 holds in exact arithmetic (the sample's leverage within its own
  // scatter is below (m − 1)/m, and κΨ only lowers q); keep rounding from
  // crossing it.
  const double remaining = std::max(1.0 - a * q, 1e-12);
  const double squared = (m - 1.0 + kappa) * a * a * q / remaining;
  return leave_one_out_log_normaliser_ - 0.5 * std::log(remaining) - 0.5 * squared;
}

std::span<const double> Component::LogDensityColumn(const Dataset& data) {
  const int done = static_cast<int>(log_density_column_.size());
  const int n = data.size();
  if (done < n) {
    log_density_column_.resize(n);
    double* out = log_density_column_.data() + done;
    SquaredMahalanobis(data.data() + done, n - done, data.stride(), out);
    for (int i = 0; i < n - done; ++i) out[i] = LogDensityFromSquaredDistance(out[i]);
  }
  return log_density_column_;
}

}  // namespace relmap::cmm
