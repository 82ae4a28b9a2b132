// One Gaussian component C_k of a class mixture (§3.1): its samples, running
// mean and scatter, weight, and the cached factor that turns a point into its
// Mahalanobis distance and log-density (§3.2).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cmm/config.h"
#include "cmm/covariance_prior.h"
#include "cmm/dataset.h"
#include "cmm/partition.h"

namespace relmap::cmm {

class Component {
 public:
  // How the component evaluates densities; decided by Refresh().
  enum class Shape {
    kGaussian,  // full factor: corrected Σ̃ = Σ + λI, or the paper2018 pseudo-inverse
    kUnit,      // m < 2 (corrected): Σ = I centred on the mean, the paper's G(s, cI)
    kHit,       // paper2018 "identity" component: a peak within ‖x − μ‖² < 1e-4, else 0
  };

  // Every factory and update takes the session's covariance prior, which
  // kPooledPrior needs (non-null) and the other estimates ignore (may be null).

  // A component holding the samples `indices` of `data` (in that order; the
  // first is its "first sample"), all of class `label`.
  static Component FromSamples(int label, std::span<const int> indices, const Dataset& data,
                               const CmmConfig& config, const CovariancePrior* prior = nullptr);
  // A component restored from its running state, bit for bit.
  static Component FromState(int label, std::vector<int> indices, Eigen::VectorXd mean,
                             Eigen::MatrixXd scatter, double weight, const Dataset& data,
                             const CmmConfig& config, const CovariancePrior* prior = nullptr);
  // The union of two components of one class (paper MERGE): samples of `a` then `b`.
  static Component Union(const Component& a, const Component& b, const Dataset& data,
                         const CmmConfig& config, const CovariancePrior* prior = nullptr);

  // Appends sample `index` (Welford update of mean and scatter) and refactors.
  void AddSample(int index, const Dataset& data, const CmmConfig& config,
                 const CovariancePrior* prior = nullptr);
  // Refactors under a new prior (the running state is unchanged).
  void Refit(const Dataset& data, const CmmConfig& config, const CovariancePrior* prior);

  int label() const { return label_; }
  int size() const { return static_cast<int>(indices_.size()); }
  const std::vector<int>& indices() const { return indices_; }
  const Eigen::VectorXd& mean() const { return mean_; }
  // Σ_i (x_i − μ)(x_i − μ)ᵀ, the centred scatter of the samples.
  const Eigen::MatrixXd& scatter() const { return scatter_; }
  // The point densities are centred on: the mean, or the first sample (switch
  // first_sample_mean, m <= 4).
  const Eigen::VectorXd& centre() const { return centre_; }
  Shape shape() const { return shape_; }

  double weight() const { return weight_; }
  void set_weight(double weight) { weight_ = weight; }

  // d²(x) = (x − μ)ᵀ Σ̃⁻¹ (x − μ) of one point (Euclidean for kUnit and kHit).
  double SquaredMahalanobis(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // d² of the rows [first, first + count) of a column-major matrix with leading
  // dimension `stride`; same values as SquaredMahalanobis, whatever the batch.
  void SquaredMahalanobis(const double* points, int count, int stride, double* out) const;
  // log G_k(x) from d²(x) (§3.2); −∞ where a kHit component gives 0.
  double LogDensityFromSquaredDistance(double squared_distance) const;
  // d²(x) from log G_k(x): the inverse of LogDensityFromSquaredDistance.
  double SquaredDistanceFromLogDensity(double log_density) const {
    return 2.0 * (log_normaliser_ - log_density);
  }

  // Under kPooledPrior: log G(x_i) of one of the component's own samples under
  // the estimate without it (§3.8, leave-one-out), from its log-density under
  // the full estimate. With δ = x_i − μ, A = (m + κ)Σ and q = δᵀA⁻¹δ, taking
  // x_i out is the rank-one downdate A − aδδᵀ, a = m/(m − 1), so by
  // Sherman–Morrison d²₋ = (m − 1 + κ)a²q/(1 − aq) and
  // log det Σ₋ = log det Σ + p log((m + κ)/(m − 1 + κ)) + log(1 − aq) (the
  // floor φ is held at its full-data value). −∞ for a component of one sample:
  // without it the component does not exist.
  double LeaveOneOutLogDensity(double log_density) const;

  // The 1-NN graph of the component's samples (positions within indices()),
  // for SPLIT. Built from scratch on first use, then kept up to date by
  // AddSample in O(m·p) instead of O(m²·p).
  const NearestNeighbourGraph& NearestNeighbours(const Dataset& data);
  // Installs a graph known from elsewhere (a split half inherits its parent's:
  // every sample's nearest neighbour lies in its own half).
  void AdoptNearestNeighbours(NearestNeighbourGraph graph) { nearest_ = std::move(graph); }

  // SPLIT's proposal for this component (§3.6, split.cpp): its two halves, or no
  // half when its 1-NN graph is connected; nullopt until proposed. A function of
  // the component's samples alone, so it is kept, like the column, until the
  // component changes: the random re-check of §3.4 mostly revisits unchanged
  // components, whose halves then cost only the rows of their columns added since.
  std::optional<std::vector<Component>>& cached_split() { return split_; }
  // The halves last proposed before the component took samples (AddSample),
  // handed over once: a half whose samples are still a half of the grown
  // component is that half, bit for bit, column included (split.cpp).
  std::vector<Component> TakeEarlierHalves() { return std::move(earlier_halves_); }

  // Identifies the component's state: a new value whenever its samples,
  // statistics or prior change, kept by copies. A union of two components
  // depends on their two states alone.
  std::uint64_t version() const { return version_; }

  // MERGE's proposals for this component (merge.cpp): its union with another
  // component of its class, as the one-element candidate model it was
  // evaluated as (with its column), keyed by the other's version(); kept until
  // this component changes, like the split.
  struct CachedUnion {
    std::uint64_t partner_version = 0;
    std::vector<Component> merged;
  };
  std::vector<CachedUnion>& cached_unions() { return unions_; }

  // The log-densities of the dataset's samples under this component, one per
  // sample: the component's column of the n×K cache (§3.8). Filled lazily:
  // only rows added since the last call are computed; any change to the
  // component clears it.
  std::span<const double> LogDensityColumn(const Dataset& data);

 private:
  Component(int label, int dimension);
  // Updates the 1-NN graph for a sample about to be appended.
  void AddToNearestNeighbours(int index, const Dataset& data);
  // Recomputes centre, shape, whitening matrix and log normaliser.
  void Refresh(const Dataset& data, const CmmConfig& config, const CovariancePrior* prior);

  int label_;
  std::vector<int> indices_;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd scatter_;
  double weight_ = 1.0;

  Eigen::VectorXd centre_;
  Shape shape_ = Shape::kUnit;
  // W with d² = ‖W(x − centre)‖²: L⁻¹ (lower triangular) or Λ^{-1/2}Vᵀ of the
  // kept eigenpairs (paper2018); row-major for the kernel.
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> whitening_;
  bool whitening_is_lower_triangular_ = true;
  // log G = log_normaliser_ − d²/2 (kGaussian, kUnit); the peak value (kHit).
  double log_normaliser_ = 0.0;
  // κ of the prior the covariance was estimated under; 0 without one.
  double pseudo_samples_ = 0.0;
  // log_normaliser_ − (p/2) log((m + κ)/(m − 1 + κ)): the part of the
  // leave-one-out log-normaliser shared by all the component's samples.
  double leave_one_out_log_normaliser_ = 0.0;

  std::vector<double> log_density_column_;
  NearestNeighbourGraph nearest_;  // empty = not built yet
  std::optional<std::vector<Component>> split_;
  std::vector<Component> earlier_halves_;
  std::vector<CachedUnion> unions_;
  std::uint64_t version_ = 0;
};

}  // namespace relmap::cmm
