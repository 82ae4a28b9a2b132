// SessionConfig <-> SessionSettings for the feature settings: both ways, the defaults of
// sessions stored before FeatureConfig existed, and the refusals.
#include "service/config_mapping.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "session/session_settings.h"

namespace relmap::service {
namespace {

using ::testing::HasSubstr;

TEST(FeatureConfigMapping, RoundTripsEveryField) {
  v1::SessionConfig config;
  config.mutable_features()->set_colour(v1::COLOUR_VARIANT_PAPER2018);
  config.mutable_features()->set_fpfh_scheme(v1::FPFH_SCHEME_RAW_POINTS);
  config.mutable_features()->set_fpfh_radius(0.04f);
  StatusOr<session::SessionSettings> settings = SettingsFromProto(config);
  ASSERT_TRUE(settings.ok()) << settings.status().message();
  const perception::FeatureConfig& features = settings->perception.features;
  EXPECT_EQ(features.colour, perception::ColourConversion::kPaper2018);
  EXPECT_EQ(features.fpfh_scheme, perception::FpfhScheme::kRawPoints);
  EXPECT_EQ(features.fpfh_radius, 0.04f);
  EXPECT_EQ(ProtoFromSettings(*settings).features().SerializeAsString(),
            config.features().SerializeAsString());
}

TEST(FeatureConfigMapping, EverySchemeMapsBackToItself) {
  for (v1::FpfhScheme scheme :
       {v1::FPFH_SCHEME_SHARED_VOXELS, v1::FPFH_SCHEME_EXACT_UNION, v1::FPFH_SCHEME_RAW_POINTS}) {
    v1::SessionConfig config;
    config.mutable_features()->set_fpfh_scheme(scheme);
    StatusOr<session::SessionSettings> settings = SettingsFromProto(config);
    ASSERT_TRUE(settings.ok());
    EXPECT_EQ(ProtoFromSettings(*settings).features().fpfh_scheme(), scheme);
  }
}

// A session stored before field 7 existed parses with no features: today's defaults.
TEST(FeatureConfigMapping, AConfigWithoutFeaturesGetsTheDefaults) {
  v1::SessionConfig stored;
  stored.set_seed(7);
  v1::SessionConfig parsed;
  ASSERT_TRUE(parsed.ParseFromString(stored.SerializeAsString()));
  StatusOr<session::SessionSettings> settings = SettingsFromProto(parsed);
  ASSERT_TRUE(settings.ok());
  const v1::FeatureConfig filled = ProtoFromSettings(*settings).features();
  EXPECT_EQ(filled.colour(), v1::COLOUR_VARIANT_CORRECTED);
  EXPECT_EQ(filled.fpfh_scheme(), v1::FPFH_SCHEME_SHARED_VOXELS);
  EXPECT_EQ(filled.fpfh_radius(), 0.05f);
}

// proto3 enums are open: numbers without a name must be refused, not read as the default.
TEST(FeatureConfigMapping, UnknownEnumValuesAreInvalidAndNamed) {
  v1::SessionConfig colour;
  colour.mutable_features()->set_colour(static_cast<v1::ColourVariant>(9));
  v1::SessionConfig scheme;
  scheme.mutable_features()->set_fpfh_scheme(static_cast<v1::FpfhScheme>(-1));
  const StatusOr<session::SessionSettings> a = SettingsFromProto(colour);
  const StatusOr<session::SessionSettings> b = SettingsFromProto(scheme);
  ASSERT_FALSE(a.ok());
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(a.status().code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(a.status().message()), HasSubstr("features.colour"));
  EXPECT_EQ(b.status().code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(b.status().message()), HasSubstr("features.fpfh_scheme"));
}

TEST(FeatureConfigMapping, ARadiusOutOfRangeFailsValidation) {
  v1::SessionConfig config;
  config.mutable_features()->set_fpfh_radius(2.0f);
  StatusOr<session::SessionSettings> settings = SettingsFromProto(config);
  ASSERT_TRUE(settings.ok());
  const Status status = session::Validate(*settings);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(status.message()), HasSubstr("features.fpfh_radius"));
}

// Unset: the paper's rule; set, the class-balanced one, and it survives the way back (a
// stored session keeps its exploration).
TEST(ExplorationConfigMapping, TheClassBalancedRuleIsKeptBothWays) {
  StatusOr<session::SessionSettings> unset = SettingsFromProto(v1::SessionConfig());
  ASSERT_TRUE(unset.ok()) << unset.status().message();
  EXPECT_EQ(unset->exploration.rule, exploration::ChoiceRule::kUncertainty);
  v1::SessionConfig config;
  config.mutable_exploration()->set_class_balanced(true);
  StatusOr<session::SessionSettings> balanced = SettingsFromProto(config);
  ASSERT_TRUE(balanced.ok()) << balanced.status().message();
  EXPECT_EQ(balanced->exploration.rule, exploration::ChoiceRule::kClassBalanced);
  const v1::SessionConfig back = ProtoFromSettings(*balanced);
  EXPECT_TRUE(back.exploration().class_balanced());
  EXPECT_FALSE(ProtoFromSettings(*unset).exploration().class_balanced());
}

}  // namespace
}  // namespace relmap::service
