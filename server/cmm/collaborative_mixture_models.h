// Collaborative Mixture Models (Le Goff et al., 2018, §3 of docs/method.md): one
// Gaussian mixture per class, grown online by Algorithm IAGMM, predicting
// P(moveable | x) with eq. (class_est).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "cmm/calibration.h"
#include "cmm/component.h"
#include "cmm/config.h"
#include "cmm/covariance_prior.h"
#include "cmm/dataset.h"
#include "cmm/snapshot.h"
#include "cmm/tolerance_threshold.h"
#include "common/random.h"
#include "common/status.h"

namespace relmap::cmm {

// What one Add() did, for logs and tests.
struct UpdateReport {
  int label = 0;
  int component = 0;             // index within the class of the component that took the sample
  int splits = 0;                // accepted splits (step 3 and the re-check)
  int merges = 0;                // accepted merges
  int candidates_evaluated = 0;  // candidate models whose log-likelihood was computed
};

// The classifier's view of a batch of points, computed in one pass over the
// components: relevance and what exploration's confidence needs.
struct Evaluation {
  Eigen::VectorXd relevance;  // P(L=1 | x), eq. (class_est); 0.5 with no component
  // min_k d²_k(x) over the components of both classes; +∞ with no component.
  Eigen::VectorXd nearest_squared_mahalanobis;
  // log of the membership probability w_k* G_k*(x) / Γ_c(x) of that nearest
  // component k* within its class c (eq. comp_est); −∞ with no component.
  Eigen::VectorXd nearest_log_membership;
  int dimension = 0;  // p, for the χ² confidence of exploration
};

class CollaborativeMixtureModels {
 public:
  // An empty model for features of `dimension` values. Invalid config → error.
  static StatusOr<CollaborativeMixtureModels> Create(const CmmConfig& config, int dimension);
  // The model a snapshot describes; an inconsistent snapshot → INVALID_ARGUMENT
  // or DATA_LOSS with what is wrong.
  static StatusOr<CollaborativeMixtureModels> Restore(const CmmSnapshot& snapshot);

  // Algorithm IAGMM (§3.4): appends (x, label) and updates the mixtures. A wrong
  // dimension, a non-finite value or a label other than 0/1 → INVALID_ARGUMENT,
  // and the model is unchanged.
  StatusOr<UpdateReport> Add(const Eigen::Ref<const Eigen::VectorXd>& x, int label);

  // Relevance, nearest distance and membership of every row of `points` (N×p),
  // in one batched pass. Rows must be finite (the caller masks the others).
  Evaluation Evaluate(const Eigen::Ref<const Eigen::MatrixXd>& points) const;
  // Eq. (class_est) for every row of `points`.
  Eigen::VectorXd Predict(const Eigen::Ref<const Eigen::MatrixXd>& points) const;

  // The acceptance criterion of §3.8 for the current model: L = Σ_i log P(L =
  // l_i | x_i) over the dataset, each sample predicted by the model as it is
  // (kTrainingLikelihood) or without that sample (kLeaveOneOut), with the
  // model's prediction rule. Fills the lazy cache.
  double LogLikelihood();

  // τ and ε of the calibrated prediction (§3.3); (1, 0) under the pseudo-count.
  const Calibration& calibration() const { return calibration_; }
  double temperature() const { return calibration_.temperature; }
  // The session's covariance prior (kPooledPrior; computed_from = 0 otherwise).
  const CovariancePrior& prior() const { return prior_; }

  CmmSnapshot Snapshot() const;

  const CmmConfig& config() const { return config_; }
  int dimension() const { return data_.dimension(); }
  const Dataset& dataset() const { return data_; }
  const std::vector<Component>& components(int label) const { return components_[label]; }
  int component_count(int label) const { return static_cast<int>(components_[label].size()); }
  int sample_count(int label) const { return data_.count(label); }
  std::uint64_t splits() const { return splits_; }
  std::uint64_t merges() const { return merges_; }

 private:
  CollaborativeMixtureModels(const CmmConfig& config, int dimension);

  // Index within `label` of the component nearest to x (Mahalanobis, §3.4 step 2).
  int NearestComponent(int label, const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // SPLIT (§3.6) and MERGE (§3.7) of components_[label][index]; true if accepted.
  bool TrySplit(int label, int index, UpdateReport& report);
  // SPLIT's two halves of `c` along the gaps of its 1-NN graph; empty when the
  // graph is connected.
  std::vector<Component> SplitHalves(Component& c);
  bool TryMerge(int label, int index, UpdateReport& report);
  // MERGE's candidate model for components_[label][index] and [k]: their union,
  // built once per pair of states (Component::cached_unions).
  std::vector<Component>& UnionCandidate(int label, int index, int k);
  // §3.4 step 3 and step 4.
  void SplitOrMerge(int label, int index, UpdateReport& report);
  void RandomRecheck(int step_two_index, UpdateReport& report);

  // Whether `candidate`'s mean lies in the tolerance ellipsoid of `c` (§3.5).
  bool Intersects(const Component& c, const Component& candidate);
  // Whether C = components_[label][index] overlaps the other class, for SPLIT:
  // with kOtherMean an other-class candidate's mean lies in C's ellipsoid,
  // with kOtherSamples an other-class sample does.
  bool OverlapsOtherClass(int label, int index);
  // The other components of a class ordered by c's Mahalanobis distance to their
  // centres, nearest first (ties: lower index), excluding `skip` (or -1).
  std::vector<int> CandidatesByDistance(const Component& c, int label, int skip) const;

  // Whether the candidate of log-odds `log_odds`, the current model's outside
  // the rows `changed`, is sure not to raise L whatever calibration it fits
  // (kCalibrated without label noise; false when it cannot tell).
  bool CannotImprove(const Eigen::VectorXd& log_odds, const std::vector<int>& changed);
  // Whether replacing class `label`'s components `removed` by `added` raises L
  // strictly (always true with the switch skip_likelihood_check).
  bool ImprovesLikelihood(int label, const std::vector<int>& removed, std::vector<Component>& added,
                          UpdateReport& report);
  // w_k = m_k / Σ_j m_j over the class (§3.1).
  void RefreshWeights(int label);
  // Forgets the cached log Γ of class `label` and L, after the class changed.
  void InvalidateLikelihood(int label);
  // Recomputes the covariance prior from the whole dataset and refits every
  // component under it (kPooledPrior, at IsPriorCheckpoint sizes).
  void RefreshPrior();
  // The prior every component is estimated under; null without kPooledPrior.
  const CovariancePrior* prior_or_null() const {
    return config_.covariance == CovarianceEstimate::kPooledPrior ? &prior_ : nullptr;
  }
  // log of the prediction's pseudo-count density at each sample: 0 (the
  // paper's "+1") or log B(x_i) (kCalibrated), extended lazily as the dataset
  // grows.
  const Eigen::VectorXd& SampleLogPseudoCounts();
  // log of the weight of that density: 0 (the paper), or log(1/(n + 1))
  // (kCalibrated): B is the density of one pseudo-sample from a component not
  // seen yet, as in a Dirichlet-process mixture's predictive, so its share
  // falls as 1/(n + 1) while far from all data it still takes over (P → ½).
  double LogPseudoCountWeight() const {
    return config_.prediction == Prediction::kCalibrated ? -std::log(data_.size() + 1.0) : 0.0;
  }
  // The criterion's log Γ of one class at every sample, for the class's
  // components `members` (with their stored weights, or m_k/Σm): under
  // kLeaveOneOut, a sample of the class is evaluated without itself, and
  // `largest`, if given, receives each row's largest term.
  Eigen::VectorXd CriterionClassLogDensity(const std::vector<Component*>& members,
                                           bool stored_weights, Eigen::VectorXd* largest = nullptr);
  // The same for the candidate that replaces class `label`'s components
  // `removed` by `added`, recomputing only the rows the change can reach (the
  // others keep the current model's bits); `changed` receives those rows.
  Eigen::VectorXd CandidateClassLogDensity(int label, const std::vector<int>& removed,
                                           std::vector<Component>& added,
                                           std::vector<int>& changed);
  // Per sample, the log-odds in favour of its label from both classes'
  // criterion densities (before calibration).
  Eigen::VectorXd SampleLogOdds(const std::array<Eigen::VectorXd, 2>& log_gamma);
  // The calibration that fits `log_odds` best, from the current one; (1, 0)
  // under the pseudo-count.
  Calibration FitCalibrationTo(const Eigen::VectorXd& log_odds) const;
  // log P(l_i | x_i) of every sample from its log-odds.
  static Eigen::VectorXd SampleLogProbabilities(const Eigen::VectorXd& log_odds,
                                                const Calibration& calibration);
  // Fills the criterion's class densities of the current model.
  void FillClassLogDensities();
  // The current model's log-odds of every sample (SampleLogOdds), kept while
  // the class densities are.
  const Eigen::VectorXd& CurrentLogOdds();
  // After a sample was appended to the dataset and before any component took
  // it: the class densities gain the new row (the old rows are those of the
  // same components and weights), and L is forgotten.
  void ExtendClassLogDensities();
  // Refits the calibration to the current model (kCalibrated): at the start of
  // every Add, once the sample is in, so that the current model and its
  // candidates are compared each with its best calibration, and at the end, for
  // the predictions. The only place calibration_ changes, so that a query of
  // LogLikelihood() leaves the model as it is (a restored model learns on bit
  // for bit like the original).
  void Recalibrate();

  CmmConfig config_;
  Dataset data_;
  std::array<std::vector<Component>, 2> components_;
  Random random_;
  ToleranceThresholdTable tolerance_;
  CovariancePrior prior_;
  Calibration calibration_;
  Eigen::VectorXd sample_log_pseudo_count_;  // empty = to be computed
  // log Γ_l(x_i) of each class, the log-odds and log P(l_i | x_i) of each
  // sample and their sum L, kept between candidate evaluations while the model
  // does not change (empty = to be computed).
  std::array<Eigen::VectorXd, 2> class_log_density_;
  // Under kLeaveOneOut, the largest term of each row of class_log_density_,
  // against which a candidate's changed terms are found negligible or not.
  std::array<Eigen::VectorXd, 2> class_log_high_;
  Eigen::VectorXd sample_log_odds_;
  Eigen::VectorXd sample_log_probability_;
  std::optional<double> log_likelihood_;
  // Σ_i z_i σ(−τ z_i) of the current log-odds at the current τ, and Σ of its
  // terms' magnitudes, for CannotImprove; kept with log_likelihood_, and each
  // sample's term in current_row_slope_.
  struct Slope {
    double gradient = 0.0;
    double magnitude = 0.0;
  };
  std::optional<Slope> current_slope_;
  Eigen::VectorXd current_row_slope_;
  // Whether CannotImprove applies: a calibrated temperature without label noise.
  bool BoundsByTemperatureSlope() const;
  // Fills current_row_slope_ and current_slope_ for `log_probability` (null: do
  // not write) at the current τ, from one exp per sample.
  void FillCurrentSlope(Eigen::VectorXd* log_probability);
  std::uint64_t splits_ = 0;
  std::uint64_t merges_ = 0;
};

}  // namespace relmap::cmm
