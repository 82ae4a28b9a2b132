// Snapshot and restore of the whole model state. The running mean and scatter of
// every component are stored as they are, not recomputed from the samples, so
// that a restored model reproduces every bit of the original.
#include "cmm/snapshot.h"

#include <cmath>
#include <string>

#include "cmm/collaborative_mixture_models.h"

namespace relmap::cmm {
namespace {

Status CheckComponent(const ComponentSnapshot& c, int label, const CmmSnapshot& s,
                      std::vector<int>& owner) {
  const auto p = static_cast<std::size_t>(s.dimension);
  const std::string where = "class " + std::to_string(label) + " component: ";
  if (c.samples.empty()) return DataLossError(where + "has no sample");
  if (c.mean.size() != p || c.scatter.size() != p * p) {
    return DataLossError(where + "mean or scatter has the wrong size");
  }
  if (!(c.weight > 0.0 && c.weight <= 1.0)) return DataLossError(where + "weight out of (0, 1]");
  for (int index : c.samples) {
    if (index < 0 || index >= static_cast<int>(s.labels.size())) {
      return DataLossError(where + "sample index " + std::to_string(index) + " out of range");
    }
    if (s.labels[index] != label) {
      return DataLossError(where + "holds sample " + std::to_string(index) + " of the other class");
    }
    if (owner[index] >= 0) {
      return DataLossError("sample " + std::to_string(index) + " belongs to two components");
    }
    owner[index] = label;
  }
  return OkStatus();
}

}  // namespace

CmmSnapshot CollaborativeMixtureModels::Snapshot() const {
  CmmSnapshot s;
  s.config = config_;
  s.dimension = dimension();
  const int n = data_.size();
  const int p = dimension();
  s.features.resize(static_cast<std::size_t>(n) * p);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < p; ++k)
      s.features[static_cast<std::size_t>(i) * p + k] = data_.sample(i)[k];
  }
  s.labels = data_.labels();
  for (int label = 0; label < 2; ++label) {
    for (const Component& c : components_[label]) {
      ComponentSnapshot cs;
      cs.samples = c.indices();
      cs.mean.assign(c.mean().data(), c.mean().data() + p);
      cs.scatter.assign(c.scatter().data(), c.scatter().data() + static_cast<std::size_t>(p) * p);
      cs.weight = c.weight();
      s.components[label].push_back(std::move(cs));
    }
  }
  s.random_state = random_.state();
  s.splits = splits_;
  s.merges = merges_;
  s.prior_pseudo_samples = prior_.pseudo_samples;
  s.temperature = calibration_.temperature;
  s.label_noise = calibration_.label_noise;
  return s;
}

StatusOr<CollaborativeMixtureModels> CollaborativeMixtureModels::Restore(const CmmSnapshot& s) {
  auto created = Create(s.config, s.dimension);
  if (!created.ok()) return created.status();
  CollaborativeMixtureModels model = std::move(created).value();
  const int p = s.dimension;
  const std::size_t n = s.labels.size();
  if (s.features.size() != n * static_cast<std::size_t>(p)) {
    return DataLossError("snapshot holds " + std::to_string(s.features.size()) +
                         " feature values for " + std::to_string(n) + " samples of dimension " +
                         std::to_string(p));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Map<const Eigen::VectorXd> x(s.features.data() + i * p, p);
    if (!x.allFinite()) return DataLossError("sample " + std::to_string(i) + " is not finite");
    if (s.labels[i] != 0 && s.labels[i] != 1) {
      return DataLossError("sample " + std::to_string(i) + " has label " +
                           std::to_string(s.labels[i]));
    }
    model.data_.Append(x, s.labels[i]);
  }

  // The prior is a function of the dataset and its size: recomputed, not stored.
  if (model.config_.covariance == CovarianceEstimate::kPooledPrior && n > 0) {
    model.prior_ =
        ComputeCovariancePrior(model.data_, PriorSampleCount(static_cast<int>(n)), model.config_);
    if (!(s.prior_pseudo_samples > 0.0) || !std::isfinite(s.prior_pseudo_samples)) {
      return DataLossError("snapshot has no valid prior pseudo-sample count");
    }
    model.prior_.pseudo_samples = s.prior_pseudo_samples;
  }
  std::vector<int> owner(n, -1);
  for (int label = 0; label < 2; ++label) {
    for (const ComponentSnapshot& c : s.components[label]) {
      if (Status status = CheckComponent(c, label, s, owner); !status.ok()) return status;
      model.components_[label].push_back(Component::FromState(
          label, c.samples, Eigen::Map<const Eigen::VectorXd>(c.mean.data(), p),
          Eigen::Map<const Eigen::MatrixXd>(c.scatter.data(), p, p), c.weight, model.data_,
          model.config_, model.prior_or_null()));
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (owner[i] < 0) return DataLossError("sample " + std::to_string(i) + " has no component");
  }
  model.random_ = Random::FromState(s.random_state);
  model.splits_ = s.splits;
  model.merges_ = s.merges;
  if (!(s.temperature >= 0.0 && s.temperature <= 1.0) ||
      !(s.label_noise >= 0.0 && s.label_noise <= 0.5)) {
    return DataLossError("snapshot calibration out of range");
  }
  model.calibration_ = {s.temperature, s.label_noise};
  return model;
}

}  // namespace relmap::cmm
