// The acceptance criterion L of §3.8 (docs/method.md), and the comparison that
// accepts a split or merge. Every component keeps its column of per-sample
// log-densities (the n×K cache), so a candidate model costs the new components'
// columns, O(n·p²) each, plus O(n·K) sums; the model itself is never copied.
// The leave-one-out criterion reads the same columns: a sample's density under
// its own component without it is a closed-form downdate of its cached value.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>

#include "cmm/calibration.h"
#include "cmm/collaborative_mixture_models.h"
#include "cmm/log_math.h"
#include "cmm/mixture_density.h"

namespace relmap::cmm {
const Eigen::VectorXd& CollaborativeMixtureModels::SampleLogPseudoCounts() {
  const int n = data_.size();
  const int done = static_cast<int>(sample_log_pseudo_count_.size());
  if (done < n) {
    sample_log_pseudo_count_.conservativeResize(n);
    if (config_.prediction == Prediction::kCalibrated && prior_.computed_from > 0) {
      prior_.BackgroundLogDensity(data_.data() + done, n - done, data_.stride(),
                                  sample_log_pseudo_count_.data() + done);
    } else {
      sample_log_pseudo_count_.tail(n - done).setZero();
    }
  }
  return sample_log_pseudo_count_;
}

namespace {

// A class's members as the criterion weighs them (§3.8): the mixture's columns
// and weights, and under leave-one-out the weights m_t/(M − 1) of the other
// components and (m_k − 1)/(M − 1) of a sample's own.
struct CriterionTerms {
  double total = 0.0;  // M
  std::vector<WeightedColumn> columns;
  std::vector<double> log_weight;      // log m_t − log(M − 1)
  std::vector<double> log_own_weight;  // log(m_t − 1) − log(M − 1)
};

CriterionTerms WeighMembers(const std::vector<Component*>& members, bool stored_weights,
                            bool leave_one_out, const Dataset& data) {
  CriterionTerms c;
  for (const Component* member : members) c.total += member->size();
  c.columns.reserve(members.size());
  for (Component* member : members) {
    const double w = stored_weights ? member->weight() : member->size() / c.total;
    c.columns.push_back({member->LogDensityColumn(data), std::log(w)});
  }
  if (!leave_one_out || c.total <= 1.0) return c;
  const double log_rest = std::log(c.total - 1.0);
  c.log_weight.reserve(members.size());
  c.log_own_weight.reserve(members.size());
  for (const Component* member : members) {
    c.log_weight.push_back(std::log(member->size()) - log_rest);
    c.log_own_weight.push_back(std::log(member->size() - 1.0) - log_rest);
  }
  return c;
}

// log Γ at sample i of members[k] taken out: component k's density without it
// (§3.8); `terms` is scratch of one value per member.
double LeaveOneOutRow(const std::vector<Component*>& members, const CriterionTerms& c,
                      std::size_t k, int i, std::vector<double>& terms, double* largest = nullptr) {
  for (std::size_t t = 0; t < members.size(); ++t) {
    terms[t] = c.log_weight[t] + c.columns[t].log_density[i];
  }
  terms[k] = c.log_own_weight[k] + members[k]->LeaveOneOutLogDensity(c.columns[k].log_density[i]);
  return LogSumExp(terms, largest);
}

}  // namespace

Eigen::VectorXd CollaborativeMixtureModels::CriterionClassLogDensity(
    const std::vector<Component*>& members, bool stored_weights, Eigen::VectorXd* largest) {
  const bool leave_one_out = config_.acceptance == AcceptanceTest::kLeaveOneOut;
  const CriterionTerms c = WeighMembers(members, stored_weights, leave_one_out, data_);
  const int n = data_.size();
  if (!leave_one_out) return MixtureLogDensity(c.columns, n);

  // The members hold every sample of their class, and those rows are set
  // below: only the other rows take the plain mixture density.
  std::vector<bool> in_class(static_cast<std::size_t>(n), false);
  for (const Component* member : members) {
    for (const int i : member->indices()) in_class[static_cast<std::size_t>(i)] = true;
  }
  Eigen::VectorXd log_gamma(n);
  Eigen::VectorXd high(n);
  for (int i = 0; i < n; ++i) {
    if (!in_class[static_cast<std::size_t>(i)]) {
      log_gamma[i] = MixtureLogDensityAt(c.columns, i, &high[i]);
    }
  }

  // Sample i of component k, taken out: weights (m_j − [j = k])/(M − 1), and
  // component k's density without it.
  std::vector<double> terms(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    for (const int i : members[k]->indices()) {
      if (c.total <= 1.0) {
        log_gamma[i] = high[i] = kNegativeInfinity;
      } else {
        log_gamma[i] = LeaveOneOutRow(members, c, k, i, terms, &high[i]);
      }
    }
  }
  if (largest != nullptr) *largest = std::move(high);
  return log_gamma;
}

Eigen::VectorXd CollaborativeMixtureModels::CandidateClassLogDensity(
    int label, const std::vector<int>& removed, std::vector<Component>& added,
    std::vector<int>& changed) {
  // The candidate differs in class `label` only: the replaced components go,
  // `added` come in, and the class's weights are m_k / Σ m_j afresh.
  auto& mixture = components_[label];
  std::vector<Component*> members;
  members.reserve(mixture.size() + added.size());
  for (int k = 0; k < static_cast<int>(mixture.size()); ++k) {
    if (std::find(removed.begin(), removed.end(), k) == removed.end()) {
      members.push_back(&mixture[k]);
    }
  }
  const std::size_t kept = members.size();
  for (Component& c : added) members.push_back(&c);

  const int n = data_.size();
  const Eigen::VectorXd& current = class_log_density_[label];
  const Eigen::VectorXd& high = class_log_high_[label];
  const CriterionTerms c =
      WeighMembers(members, false, config_.acceptance == AcceptanceTest::kLeaveOneOut, data_);
  // The rows are compared with the current model's below when both weigh the
  // components alike: by leave-one-out, with weights m_k / Σ m_j (not stale).
  if (config_.acceptance != AcceptanceTest::kLeaveOneOut || config_.switches.stale_weights ||
      c.total <= 1.0 || current.size() != n || high.size() != n) {
    changed.resize(static_cast<std::size_t>(n));
    std::iota(changed.begin(), changed.end(), 0);
    return CriterionClassLogDensity(members, false);
  }

  // The removed components' terms in the current model, in a row of the class
  // (leave-one-out weight) and in a row of the other class (mixture weight).
  struct Removed {
    std::span<const double> column;
    double log_weight;
    double log_mixture_weight;
  };
  const double log_rest = std::log(c.total - 1.0);
  std::vector<Removed> gone;
  gone.reserve(removed.size());
  for (const int r : removed) {
    Component& g = mixture[r];
    gone.push_back(
        {g.LogDensityColumn(data_), std::log(g.size()) - log_rest, std::log(g.weight())});
  }
  std::vector<int> owner(static_cast<std::size_t>(n), -1);  // position in `members`
  for (std::size_t t = 0; t < members.size(); ++t) {
    for (const int i : members[t]->indices())
      owner[static_cast<std::size_t>(i)] = static_cast<int>(t);
  }

  // A row whose own component stays, and where every term that goes or comes
  // lies kNegligibleLogTerm or more below the current largest term, has the
  // same largest term and sums the same terms in the same order: the same bits.
  // In 48-d most rows are far from the changed components.
  Eigen::VectorXd log_gamma = current;
  std::vector<double> terms(members.size());
  for (int i = 0; i < n; ++i) {
    const int k = owner[static_cast<std::size_t>(i)];
    bool reached = k >= static_cast<int>(kept) || !std::isfinite(high[i]);
    for (std::size_t g = 0; g < gone.size() && !reached; ++g) {
      const double log_weight = k >= 0 ? gone[g].log_weight : gone[g].log_mixture_weight;
      reached = log_weight + gone[g].column[i] - high[i] > -kNegligibleLogTerm;
    }
    for (std::size_t t = kept; t < members.size() && !reached; ++t) {
      const double log_weight = k >= 0 ? c.log_weight[t] : c.columns[t].log_weight;
      reached = log_weight + c.columns[t].log_density[i] - high[i] > -kNegligibleLogTerm;
    }
    if (!reached) continue;
    log_gamma[i] = k >= 0 ? LeaveOneOutRow(members, c, static_cast<std::size_t>(k), i, terms)
                          : MixtureLogDensityAt(c.columns, i);
    changed.push_back(i);
  }
  return log_gamma;
}

Eigen::VectorXd CollaborativeMixtureModels::SampleLogOdds(
    const std::array<Eigen::VectorXd, 2>& log_gamma) {
  const int n = data_.size();
  const Eigen::VectorXd& log_pseudo = SampleLogPseudoCounts();
  const double log_weight = LogPseudoCountWeight();
  Eigen::VectorXd z(n);
  for (int i = 0; i < n; ++i) {
    const int l = data_.label(i);
    z[i] = LogOdds(log_gamma[l][i], log_gamma[1 - l][i], log_weight + log_pseudo[i]);
  }
  return z;
}

Calibration CollaborativeMixtureModels::FitCalibrationTo(const Eigen::VectorXd& log_odds) const {
  if (config_.prediction != Prediction::kCalibrated) return Calibration{};
  // From the model's current calibration: a warm start, a few Newton or EM
  // steps instead of dozens.
  const std::span<const double> z{log_odds.data(), static_cast<std::size_t>(log_odds.size())};
  return config_.fit_label_noise
             ? FitCalibration(z, calibration_)
             : Calibration{FitTemperature(z, {}, calibration_.temperature), 0.0};
}

Eigen::VectorXd CollaborativeMixtureModels::SampleLogProbabilities(const Eigen::VectorXd& log_odds,
                                                                   const Calibration& calibration) {
  Eigen::VectorXd out(log_odds.size());
  for (Eigen::Index i = 0; i < log_odds.size(); ++i) {
    out[i] = LogCalibratedProbability(log_odds[i], calibration);
  }
  return out;
}

void CollaborativeMixtureModels::FillClassLogDensities() {
  for (int label = 0; label < 2; ++label) {
    if (class_log_density_[label].size() != data_.size()) {
      std::vector<Component*> members;
      members.reserve(components_[label].size());
      for (Component& c : components_[label]) members.push_back(&c);
      class_log_density_[label] = CriterionClassLogDensity(members, true, &class_log_high_[label]);
    }
  }
}

void CollaborativeMixtureModels::ExtendClassLogDensities() {
  const int n = data_.size();
  for (int label = 0; label < 2; ++label) {
    Eigen::VectorXd& log_gamma = class_log_density_[label];
    Eigen::VectorXd& high = class_log_high_[label];
    // With stale weights a component takes samples without its class's
    // densities being forgotten, so they may not be those of the model.
    if (log_gamma.size() != n - 1 || config_.switches.stale_weights) {
      log_gamma.resize(0);
      high.resize(0);
      continue;
    }
    // The new sample is in no component yet: its row is the plain mixture
    // density, under either criterion, and the other rows do not change.
    std::vector<WeightedColumn> columns;
    columns.reserve(components_[label].size());
    for (Component& c : components_[label]) {
      columns.push_back({c.LogDensityColumn(data_), std::log(c.weight())});
    }
    log_gamma.conservativeResize(n);
    double largest = kNegativeInfinity;
    log_gamma[n - 1] = MixtureLogDensityAt(columns, n - 1, &largest);
    if (high.size() == n - 1) {
      high.conservativeResize(n);
      high[n - 1] = largest;
    } else {
      high.resize(0);
    }
  }
  sample_log_odds_.resize(0);
  sample_log_probability_.resize(0);
  log_likelihood_.reset();
}

void CollaborativeMixtureModels::Recalibrate() {
  if (config_.prediction != Prediction::kCalibrated) return;
  calibration_ = FitCalibrationTo(CurrentLogOdds());
  sample_log_probability_.resize(0);
  log_likelihood_.reset();
}

const Eigen::VectorXd& CollaborativeMixtureModels::CurrentLogOdds() {
  FillClassLogDensities();
  if (sample_log_odds_.size() != data_.size()) sample_log_odds_ = SampleLogOdds(class_log_density_);
  return sample_log_odds_;
}

double CollaborativeMixtureModels::LogLikelihood() {
  if (log_likelihood_) return *log_likelihood_;
  const Eigen::VectorXd& log_odds = CurrentLogOdds();
  current_slope_.reset();
  if (BoundsByTemperatureSlope() && calibration_.label_noise <= 0.0) {
    // The probabilities and CannotImprove's slopes share their exp.
    sample_log_probability_.resize(log_odds.size());
    FillCurrentSlope(&sample_log_probability_);
  } else {
    sample_log_probability_ = SampleLogProbabilities(log_odds, calibration_);
  }
  log_likelihood_ = sample_log_probability_.sum();
  return *log_likelihood_;
}

bool CollaborativeMixtureModels::BoundsByTemperatureSlope() const {
  return config_.prediction == Prediction::kCalibrated && !config_.fit_label_noise;
}

void CollaborativeMixtureModels::FillCurrentSlope(Eigen::VectorXd* log_probability) {
  const double tau = calibration_.temperature;
  current_row_slope_.resize(sample_log_odds_.size());
  Slope sum;
  for (Eigen::Index i = 0; i < sample_log_odds_.size(); ++i) {
    const ProbabilityAndSlope at = LogProbabilityAndSlope(sample_log_odds_[i], tau);
    if (log_probability != nullptr) (*log_probability)[i] = at.log_probability;
    current_row_slope_[i] = at.slope;
    sum.gradient += at.slope;
    sum.magnitude += std::abs(at.slope);
  }
  current_slope_ = sum;
}

bool CollaborativeMixtureModels::CannotImprove(const Eigen::VectorXd& log_odds,
                                               const std::vector<int>& changed) {
  if (!BoundsByTemperatureSlope()) return false;
  // f(τ) = Σ_i log σ(τ z_i) is concave, so below its tangent at the current τ₀:
  // the candidate's L at its best τ is at most f(τ₀) + max(−τ₀, 1 − τ₀)·f′(τ₀).
  // f(τ₀) − L and f′(τ₀) differ from the current model's in the changed rows
  // only. When that bound is below 0 by more than any rounding of the sums (a
  // relative 1e−7 of their magnitudes, against n·2⁻⁵³), the fitted ΔL could
  // not be positive either, so the fit is skipped: the same decision.
  const double tau = calibration_.temperature;
  if (!current_slope_) FillCurrentSlope(nullptr);
  double gain = 0.0;  // f(τ₀) − L
  double gradient = current_slope_->gradient;
  double magnitude = current_slope_->magnitude - *log_likelihood_;  // −L = Σ |log P|
  for (const int i : changed) {
    const ProbabilityAndSlope at = LogProbabilityAndSlope(log_odds[i], tau);
    gain += at.log_probability - sample_log_probability_[i];
    const double current_slope = current_row_slope_[i];
    gradient += at.slope - current_slope;
    magnitude += std::abs(at.log_probability) + std::abs(at.slope) + std::abs(current_slope);
  }
  const double bound = gain + std::max(-tau * gradient, (1.0 - tau) * gradient);
  return bound < -1e-7 * (1.0 + magnitude + std::abs(gradient));
}

bool CollaborativeMixtureModels::ImprovesLikelihood(int label, const std::vector<int>& removed,
                                                    std::vector<Component>& added,
                                                    UpdateReport& report) {
  if (config_.switches.skip_likelihood_check) return true;
  ++report.candidates_evaluated;
  LogLikelihood();  // fills the caches of the current model

  // Only the rows whose class density changed can change their log-odds.
  std::vector<int> changed;
  const Eigen::VectorXd log_gamma = CandidateClassLogDensity(label, removed, added, changed);
  Eigen::VectorXd log_odds = sample_log_odds_;
  const Eigen::VectorXd& log_pseudo = SampleLogPseudoCounts();
  const double log_weight = LogPseudoCountWeight();
  for (const int i : changed) {
    const int l = data_.label(i);
    const double own = l == label ? log_gamma[i] : class_log_density_[l][i];
    const double other = l == label ? class_log_density_[1 - l][i] : log_gamma[i];
    log_odds[i] = LogOdds(own, other, log_weight + log_pseudo[i]);
  }

  if (CannotImprove(log_odds, changed)) return false;

  // ΔL as a sum of per-sample differences rather than a difference of two sums:
  // samples the change does not reach contribute exactly 0, so rounding in the
  // sum over all n samples cannot fake a strict increase.
  const Eigen::VectorXd candidate = SampleLogProbabilities(log_odds, FitCalibrationTo(log_odds));
  return (candidate - sample_log_probability_).sum() > 0.0;
}

}  // namespace relmap::cmm
