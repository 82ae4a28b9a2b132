// The whole state of a CollaborativeMixtureModels as plain data: what the
// session layer persists and exports. Restoring it gives a model that predicts
// and learns bit for bit like the original.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cmm/config.h"
#include "common/random.h"

namespace relmap::cmm {

struct ComponentSnapshot {
  std::vector<int> samples;     // dataset indices, first sample first
  std::vector<double> mean;     // p values
  std::vector<double> scatter;  // p×p, column-major
  double weight = 0.0;
};

struct CmmSnapshot {
  CmmConfig config;
  int dimension = 0;
  std::vector<double> features;  // n×p, row-major: sample i is [i*p, (i+1)*p)
  std::vector<std::int8_t> labels;
  std::array<std::vector<ComponentSnapshot>, 2> components;  // per class
  Random::State random_state{};
  std::uint64_t splits = 0;
  std::uint64_t merges = 0;
  // κ of the covariance prior as last chosen (kPooledPrior; 0 otherwise). The
  // prior's scale is recomputed from the samples, κ cannot be: it was chosen
  // against the model as it stood at the checkpoint.
  double prior_pseudo_samples = 0.0;
  // The calibration of the prediction (kCalibrated): fitted by an iteration
  // warm-started from the previous one, so stored rather than refitted.
  double temperature = 1.0;
  double label_noise = 0.0;
};

}  // namespace relmap::cmm
