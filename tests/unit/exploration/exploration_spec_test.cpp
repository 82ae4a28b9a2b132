// The exploration options as text: parse, name, reject.
#include "exploration/exploration_spec.h"

#include <gtest/gtest.h>

namespace relmap::exploration {
namespace {

TEST(ExplorationSpec, ReadsAndNamesEveryOption) {
  for (const std::string spec : {"paper", "novelty", "random=0.25", "novelty,random=0.1",
                                 "balanced", "balanced,novelty,random=0.1"}) {
    ExplorationConfig config;
    ASSERT_TRUE(ApplyExplorationSpec(spec, config).ok()) << spec;
    EXPECT_EQ(ExplorationSpec(config), spec);
  }
}

TEST(ExplorationSpec, PaperResetsTheOptionsAndLeavesTheRest) {
  ExplorationConfig config;
  config.paper_choice_quirks = true;
  ASSERT_TRUE(ApplyExplorationSpec("balanced,novelty,random=0.5,paper", config).ok());
  EXPECT_EQ(config.rule, ChoiceRule::kUncertainty);
  EXPECT_EQ(config.diversity, Diversity::kNone);
  EXPECT_EQ(config.random_share, 0.0);
  EXPECT_TRUE(config.paper_choice_quirks);
}

TEST(ExplorationSpec, RejectsUnknownWordsAndSharesOutsideZeroOne) {
  for (const char* spec :
       {"greedy", "random=", "random=1.5", "random=-0.1", "random=nan", "novelty,,x"}) {
    ExplorationConfig config;
    const Status status = ApplyExplorationSpec(spec, config);
    EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << spec;
  }
}

}  // namespace
}  // namespace relmap::exploration
