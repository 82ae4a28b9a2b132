// The benchmark's learners by name: CMM configurations (any text
// cmm::ParseConfiguration reads, plus `alpha1`) and the baselines gnb, sgd and knn.
#pragma once

#include <cstdint>
#include <memory>
#include <string_view>

#include "learning_bench/online_learner.h"

namespace relmap::learning_bench {

// The list the benchmark runs when the user names none.
inline constexpr std::string_view kDefaultLearners =
    "corrected,corrected_v1,paper2018,alpha1,gnb,sgd,knn";

// A fresh learner for samples of `dimension` values. A CMM name is passed to
// cmm::ParseConfiguration as it is ("corrected", "corrected:acceptance=training"),
// so that variants and options added to the classifier need no change here; `alpha1` is `corrected`
// with α = 1 (no split, no merge: one Gaussian per class, the paper's ablation). CMMs draw from
// `seed`. An unknown name → INVALID_ARGUMENT.
StatusOr<std::unique_ptr<OnlineLearner>> MakeLearner(std::string_view name, int dimension,
                                                     std::uint64_t seed);

}  // namespace relmap::learning_bench
