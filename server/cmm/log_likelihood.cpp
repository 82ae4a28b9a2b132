// The labelled log-likelihood L of the dataset (§3.8), and the comparison that
// accepts a split or merge. Every component keeps its column of per-sample
// log-densities (the n×K cache), so a candidate model costs the new components'
// columns, O(n·p²) each, plus O(n·K) sums; the model itself is never copied.
#include <algorithm>
#include <span>

#include "cmm/collaborative_mixture_models.h"
#include "cmm/log_math.h"
#include "cmm/mixture_density.h"

namespace relmap::cmm {
namespace {

// log Γ of a class with its stored weights.
Eigen::VectorXd ClassLogDensity(std::vector<Component>& mixture, const Dataset& data) {
  std::vector<WeightedColumn> columns;
  columns.reserve(mixture.size());
  for (Component& c : mixture) columns.push_back({c.LogDensityColumn(data), std::log(c.weight())});
  return MixtureLogDensity(columns, data.size());
}

// log P(l_i | x_i) of every sample (eq. class_est), from both classes' log Γ.
Eigen::VectorXd SampleLogProbabilities(const Dataset& data,
                                       const std::array<Eigen::VectorXd, 2>& log_gamma) {
  Eigen::VectorXd out(data.size());
  for (int i = 0; i < data.size(); ++i) {
    const int l = data.label(i);
    out[i] = LogClassProbability(log_gamma[l][i], log_gamma[1 - l][i]);
  }
  return out;
}

}  // namespace

double CollaborativeMixtureModels::LogLikelihood() {
  if (log_likelihood_) return *log_likelihood_;
  for (int label = 0; label < 2; ++label) {
    if (class_log_density_[label].size() != data_.size()) {
      class_log_density_[label] = ClassLogDensity(components_[label], data_);
    }
  }
  sample_log_probability_ = SampleLogProbabilities(data_, class_log_density_);
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
  double total = 0.0;
  for (const Component* c : members) total += c->size();
  std::vector<WeightedColumn> columns;
  columns.reserve(members.size());
  for (Component* c : members) {
    columns.push_back({c->LogDensityColumn(data_), std::log(c->size() / total)});
  }
  std::array<Eigen::VectorXd, 2> log_gamma = class_log_density_;
  log_gamma[label] = MixtureLogDensity(columns, data_.size());

  // ΔL as a sum of per-sample differences rather than a difference of two sums:
  // samples the change does not reach contribute exactly 0, so rounding in the
  // sum over all n samples cannot fake a strict increase.
  const Eigen::VectorXd candidate = SampleLogProbabilities(data_, log_gamma);
  return (candidate - sample_log_probability_).sum() > 0.0;
}

}  // namespace relmap::cmm
