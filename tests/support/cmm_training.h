// Shared helpers of the classifier tests: training a model on a labelled set.
#pragma once

#include <gtest/gtest.h>

#include "cmm/collaborative_mixture_models.h"
#include "datasets/synthetic_problems.h"

namespace relmap::testing {

// Adds the rows of `samples` [first, last) in order; fails the test on an error.
inline void AddRows(cmm::CollaborativeMixtureModels& model,
                    const datasets::LabelledSamples& samples, int first, int last) {
  for (int i = first; i < last; ++i) {
    const auto report = model.Add(samples.features.row(i).transpose(), samples.labels[i]);
    ASSERT_TRUE(report.ok()) << report.status().message();
  }
}

// A model trained on every row of `samples` in order.
inline cmm::CollaborativeMixtureModels Train(const datasets::LabelledSamples& samples,
                                             const cmm::CmmConfig& config) {
  auto model =
      cmm::CollaborativeMixtureModels::Create(config, static_cast<int>(samples.features.cols()));
  EXPECT_TRUE(model.ok());
  AddRows(*model, samples, 0, static_cast<int>(samples.features.rows()));
  return std::move(model).value();
}

inline datasets::LabelledSamples Problem(datasets::Problem problem, int samples, int dimension,
                                         std::uint64_t seed) {
  datasets::ProblemOptions options;
  options.problem = problem;
  options.samples = samples;
  options.dimension = dimension;
  options.seed = seed;
  return datasets::MakeProblem(options);
}

}  // namespace relmap::testing
