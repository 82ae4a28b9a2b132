// The acceptance criterion L of §3.8 (docs/method.md), and the comparison that
// accepts a split or merge. Every component keeps its column of per-sample
// log-densities (the n×K cache), so a candidate model costs the new components'
// columns, O(n·p²) each, plus O(n·K) sums; the model itself is never copied.
// The leave-one-out criterion reads the same columns: a sample's density under
// its own component without it is a closed-form downdate of its cached value.
#include <algorithm>
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

Eigen::VectorXd CollaborativeMixtureModels::CriterionClassLogDensity(
    const std::vector<Component*>& members, bool stored_weights) {
  double total = 0.0;
  for (const Component* c : members) total += c->size();
  std::vector<WeightedColumn> columns;
  columns.reserve(members.size());
  for (Component* c : members) {
    const double w = stored_weights ? c->weight() : c->size() / total;
    columns.push_back({c->LogDensityColumn(data_), std::log(w)});
  }
  if (config_.acceptance != AcceptanceTest::kLeaveOneOut) {
    return MixtureLogDensity(columns, data_.size());
  }

  // The members hold every sample of their class, and those rows are set
  // below: only the other rows take the plain mixture density.
  const int n = data_.size();
  std::vector<bool> in_class(static_cast<std::size_t>(n), false);
  for (const Component* c : members) {
    for (const int i : c->indices()) in_class[static_cast<std::size_t>(i)] = true;
  }
  Eigen::VectorXd log_gamma(n);
  for (int i = 0; i < n; ++i) {
    if (!in_class[static_cast<std::size_t>(i)]) log_gamma[i] = MixtureLogDensityAt(columns, i);
  }

  // Sample i of component k, taken out: weights (m_j − [j = k])/(M − 1), and
  // component k's density without it.
  if (total <= 1.0) {
    for (const Component* c : members) {
      for (const int i : c->indices()) log_gamma[i] = kNegativeInfinity;
    }
    return log_gamma;
  }
  const double log_rest = std::log(total - 1.0);
  std::vector<double> log_weight(members.size());
  for (std::size_t t = 0; t < members.size(); ++t) {
    log_weight[t] = std::log(members[t]->size()) - log_rest;
  }
  std::vector<double> terms(members.size());
  for (std::size_t k = 0; k < members.size(); ++k) {
    const Component& own = *members[k];
    const double log_own_weight = std::log(own.size() - 1.0) - log_rest;
    for (const int i : own.indices()) {
      for (std::size_t t = 0; t < members.size(); ++t) {
        terms[t] = log_weight[t] + columns[t].log_density[i];
      }
      terms[k] = log_own_weight + own.LeaveOneOutLogDensity(columns[k].log_density[i]);
      log_gamma[i] = LogSumExp(terms);
    }
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
      for (Component& c : components_[label]) members.push_back(&c);
      class_log_density_[label] = CriterionClassLogDensity(members, true);
    }
  }
}

void CollaborativeMixtureModels::ExtendClassLogDensities() {
  const int n = data_.size();
  for (int label = 0; label < 2; ++label) {
    Eigen::VectorXd& log_gamma = class_log_density_[label];
    // With stale weights a component takes samples without its class's
    // densities being forgotten, so they may not be those of the model.
    if (log_gamma.size() != n - 1 || config_.switches.stale_weights) {
      log_gamma.resize(0);
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
    log_gamma[n - 1] = MixtureLogDensityAt(columns, n - 1);
  }
  sample_log_probability_.resize(0);
  log_likelihood_.reset();
}

void CollaborativeMixtureModels::Recalibrate() {
  if (config_.prediction != Prediction::kCalibrated) return;
  FillClassLogDensities();
  calibration_ = FitCalibrationTo(SampleLogOdds(class_log_density_));
  sample_log_probability_.resize(0);
  log_likelihood_.reset();
}

double CollaborativeMixtureModels::LogLikelihood() {
  if (log_likelihood_) return *log_likelihood_;
  FillClassLogDensities();
  sample_log_probability_ = SampleLogProbabilities(SampleLogOdds(class_log_density_), calibration_);
  log_likelihood_ = sample_log_probability_.sum();
  return *log_likelihood_;
}

bool CollaborativeMixtureModels::ImprovesLikelihood(int label, const std::vector<int>& removed,
                                                    std::vector<Component>& added,
                                                    UpdateReport& report) {
  if (config_.switches.skip_likelihood_check) return true;
  ++report.candidates_evaluated;
  LogLikelihood();  // fills the caches of the current model

  // The candidate differs in class `label` only: the replaced components go,
  // `added` come in, and the class's weights are m_k / Σ m_j afresh.
  std::vector<Component*> members;
  for (int k = 0; k < static_cast<int>(components_[label].size()); ++k) {
    if (std::find(removed.begin(), removed.end(), k) == removed.end()) {
      members.push_back(&components_[label][k]);
    }
  }
  for (Component& c : added) members.push_back(&c);
  std::array<Eigen::VectorXd, 2> log_gamma = class_log_density_;
  log_gamma[label] = CriterionClassLogDensity(members, false);

  // ΔL as a sum of per-sample differences rather than a difference of two sums:
  // samples the change does not reach contribute exactly 0, so rounding in the
  // sum over all n samples cannot fake a strict increase.
  const Eigen::VectorXd log_odds = SampleLogOdds(log_gamma);
  const Eigen::VectorXd candidate = SampleLogProbabilities(log_odds, FitCalibrationTo(log_odds));
  return (candidate - sample_log_probability_).sum() > 0.0;
}

}  // namespace relmap::cmm
