// CMM configurations as text (cmm/config_spec.h): presets, options, names.
#include "cmm/config_spec.h"

#include <gtest/gtest.h>

namespace relmap::cmm {
namespace {

TEST(ParseConfiguration, AVariantAloneIsItsPreset) {
  const auto corrected = ParseConfiguration("corrected");
  ASSERT_TRUE(corrected.ok());
  EXPECT_EQ(corrected->covariance, CovarianceEstimate::kPooledPrior);
  EXPECT_EQ(corrected->acceptance, AcceptanceTest::kLeaveOneOut);
  EXPECT_EQ(corrected->split_overlap, SplitOverlap::kOtherSamples);
  EXPECT_EQ(corrected->prediction, Prediction::kCalibrated);
  const auto v1 = ParseConfiguration("corrected_v1");
  ASSERT_TRUE(v1.ok());
  EXPECT_EQ(v1->variant, Variant::kCorrectedV1);
  EXPECT_EQ(v1->covariance, CovarianceEstimate::kRidge);
  EXPECT_EQ(v1->acceptance, AcceptanceTest::kTrainingLikelihood);
  EXPECT_EQ(v1->split_overlap, SplitOverlap::kOtherMean);
  EXPECT_EQ(v1->prediction, Prediction::kPseudoCount);
  EXPECT_FALSE(v1->switches.pseudo_density);
  EXPECT_TRUE(ParseConfiguration("paper2018")->switches.pseudo_density);
}

TEST(ParseConfiguration, ChangesTheNamedOptions) {
  const auto c =
      ParseConfiguration("corrected:acceptance=training:prediction=pseudo_count:alpha=1");
  ASSERT_TRUE(c.ok()) << c.status().message();
  EXPECT_EQ(c->acceptance, AcceptanceTest::kTrainingLikelihood);
  EXPECT_EQ(c->prediction, Prediction::kPseudoCount);
  EXPECT_EQ(c->alpha, 1.0);
  EXPECT_EQ(c->covariance, CovarianceEstimate::kPooledPrior);  // unchanged
  EXPECT_EQ(c->max_merge_candidates, 4);
  EXPECT_EQ(ParseConfiguration("corrected:max_merge_candidates=0")->max_merge_candidates, 0);
  EXPECT_EQ(ParseConfiguration("corrected_v1")->max_merge_candidates, 0);
}

TEST(ParseConfiguration, RefusesWhatItCannotRead) {
  for (const char* bad : {"nope", "corrected:bogus=1", "corrected:alpha", "corrected:alpha=x",
                          "corrected:overlap=sideways", "corrected:alpha=2",
                          "corrected:max_merge_candidates=-1", "corrected:max_merge_candidates=1.5",
                          "corrected:covariance=ridge",  // the leave-one-out test needs the prior
                          "paper2018:covariance=prior"}) {  // the prior excludes the pseudo density
    EXPECT_EQ(ParseConfiguration(bad).status().code(), StatusCode::kInvalidArgument) << bad;
  }
}

TEST(ConfigurationName, NamesWhatDiffersFromThePresetAndReadsBack) {
  EXPECT_EQ(ConfigurationName(CmmConfig::ForVariant(Variant::kCorrected)), "corrected");
  const std::string spec = "corrected:pseudo_samples=8:acceptance=training";
  const auto parsed = ParseConfiguration(spec);
  ASSERT_TRUE(parsed.ok());
  EXPECT_EQ(ConfigurationName(*parsed), spec);
  EXPECT_EQ(ConfigurationName(*ParseConfiguration(ConfigurationName(*parsed))), spec);
}

}  // namespace
}  // namespace relmap::cmm
