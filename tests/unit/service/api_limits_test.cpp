// The table of the API's ranges: every numeric field of SessionConfig has one, each bound
// is accepted and the number just beyond it refused with the field's API name, and enum
// fields hold only the values their enum names.
#include "service/api_limits.h"

#include <gmock/gmock.h>
#include <google/protobuf/descriptor.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "perception/perception_config.h"

namespace relmap::service {
namespace {

using google::protobuf::Descriptor;
using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using ::testing::HasSubstr;

bool IsNumber(const FieldDescriptor& field) {
  switch (field.cpp_type()) {
    case FieldDescriptor::CPPTYPE_INT32:
    case FieldDescriptor::CPPTYPE_INT64:
    case FieldDescriptor::CPPTYPE_UINT32:
    case FieldDescriptor::CPPTYPE_UINT64:
    case FieldDescriptor::CPPTYPE_FLOAT:
    case FieldDescriptor::CPPTYPE_DOUBLE:
      return true;
    default:
      return false;
  }
}

void NumericPaths(const Descriptor& message, const std::string& prefix,
                  std::vector<std::string>& out) {
  for (int f = 0; f < message.field_count(); ++f) {
    const FieldDescriptor& field = *message.field(f);
    if (field.cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE) {
      NumericPaths(*field.message_type(), prefix + field.name() + ".", out);
    } else if (IsNumber(field)) {
      out.push_back(prefix + field.name());
    }
  }
}

// Sets the field at `path` of `config` to `value` (converted to the field's type).
const FieldDescriptor* Set(v1::SessionConfig& config, const std::string& path, double value) {
  Message* at = &config;
  std::string rest = path;
  for (std::size_t dot; (dot = rest.find('.')) != std::string::npos; rest.erase(0, dot + 1)) {
    at = at->GetReflection()->MutableMessage(
        at, at->GetDescriptor()->FindFieldByName(rest.substr(0, dot)));
  }
  const FieldDescriptor* field = at->GetDescriptor()->FindFieldByName(rest);
  const auto& reflection = *at->GetReflection();
  switch (field->cpp_type()) {
    case FieldDescriptor::CPPTYPE_INT32:
      reflection.SetInt32(at, field, static_cast<std::int32_t>(value));
      break;
    case FieldDescriptor::CPPTYPE_UINT32:
      reflection.SetUInt32(at, field, static_cast<std::uint32_t>(value));
      break;
    case FieldDescriptor::CPPTYPE_UINT64:
      reflection.SetUInt64(at, field, static_cast<std::uint64_t>(value));
      break;
    case FieldDescriptor::CPPTYPE_FLOAT:
      reflection.SetFloat(at, field, static_cast<float>(value));
      break;
    case FieldDescriptor::CPPTYPE_DOUBLE:
      reflection.SetDouble(at, field, value);
      break;
    default:
      ADD_FAILURE() << path << " is not a number this test sets";
  }
  return field;
}

Status CheckWith(const std::string& path, double value) {
  v1::SessionConfig config;
  Set(config, path, value);
  return CheckSessionConfig(config, "config.");
}

bool IsInteger(const FieldDescriptor& field) {
  return field.cpp_type() != FieldDescriptor::CPPTYPE_FLOAT &&
         field.cpp_type() != FieldDescriptor::CPPTYPE_DOUBLE;
}

// The representable value just beyond `bound` in `direction`, in the field's own type.
double JustBeyond(const FieldDescriptor& field, double bound, double direction) {
  if (IsInteger(field)) return bound + direction;
  if (field.cpp_type() == FieldDescriptor::CPPTYPE_FLOAT) {
    return std::nextafter(static_cast<float>(bound),
                          static_cast<float>(direction) * std::numeric_limits<float>::infinity());
  }
  return std::nextafter(bound, direction * std::numeric_limits<double>::infinity());
}

TEST(SessionConfigRanges, EveryNumericFieldHasARange) {
  std::vector<std::string> paths;
  NumericPaths(*v1::SessionConfig::descriptor(), "", paths);
  ASSERT_FALSE(paths.empty());
  for (const std::string& path : paths) {
    EXPECT_NE(SessionConfigRange(path), nullptr) << path << " has no documented range";
  }
  EXPECT_EQ(SessionConfigRanges().size(), paths.size());  // and no range of a field that is not
}

TEST(SessionConfigRanges, EachBoundIsAcceptedAndTheValueJustBeyondItRefused) {
  for (const FieldRange& range : SessionConfigRanges()) {
    const std::string path(range.field);
    SCOPED_TRACE(path);
    v1::SessionConfig probe;
    const FieldDescriptor& field = *Set(probe, path, 1);
    if (field.cpp_type() == FieldDescriptor::CPPTYPE_UINT64) continue;  // the seed: any value
    const double min = range.min_open ? JustBeyond(field, range.min, +1) : range.min;
    EXPECT_TRUE(CheckWith(path, min).ok()) << CheckWith(path, min).message();
    EXPECT_TRUE(CheckWith(path, range.max).ok()) << CheckWith(path, range.max).message();

    const double below = range.min_open ? range.min : JustBeyond(field, range.min, -1);
    const bool below_is_unset = below == 0.0 && !field.has_presence();
    const bool below_fits = !(field.cpp_type() == FieldDescriptor::CPPTYPE_UINT32 && below < 0);
    if (!below_is_unset && below_fits) {
      const Status status = CheckWith(path, below);
      EXPECT_EQ(status.code(), StatusCode::kInvalidArgument) << below;
      EXPECT_THAT(std::string(status.message()), HasSubstr("config." + path));
      EXPECT_THAT(std::string(status.message()), HasSubstr(" must lie in "));
    }
    const Status above = CheckWith(path, JustBeyond(field, range.max, +1));
    EXPECT_EQ(above.code(), StatusCode::kInvalidArgument);
    EXPECT_THAT(std::string(above.message()), HasSubstr("config." + path));
  }
}

TEST(SessionConfigRanges, NaNAndInfinitiesAreRefusedInEveryFloatingField) {
  for (const FieldRange& range : SessionConfigRanges()) {
    v1::SessionConfig probe;
    if (IsInteger(*Set(probe, std::string(range.field), 1))) continue;
    for (const double value :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()}) {
      SCOPED_TRACE(std::string(range.field) + " = " + std::to_string(value));
      EXPECT_EQ(CheckWith(std::string(range.field), value).code(), StatusCode::kInvalidArgument);
    }
  }
}

TEST(SessionConfigRanges, TheMessageNamesTheFieldTheRangeAndTheValue) {
  EXPECT_EQ(CheckWith("supervoxels.voxel_resolution", 2).message(),
            "config.supervoxels.voxel_resolution must lie in [0.001, 1] m, got 2");
  EXPECT_EQ(CheckWith("classifier.regularization", 0).message(),
            "config.classifier.regularization must lie in (0, 1000000], got 0");
  EXPECT_EQ(CheckWith("change_detector.sor_mean_k", 0).message(),
            "config.change_detector.sor_mean_k: change.sor_mean_k must lie in [1, 1000], got 0");
}

TEST(SessionConfigRanges, AnEmptyConfigTakesTheDefaultsAndPasses) {
  EXPECT_TRUE(CheckSessionConfig(v1::SessionConfig(), "config.").ok());
}

// PCL's octree over the allowed coordinates (|x| <= 100 m, a 200 m cube) has
// ceil(log2(200 / resolution)) levels: 1 mm gives ceil(17.61) = 18 <= 21, and the finest
// cell within 21 levels is 200 / 2^21 = 9.54e-5 m.
TEST(OctreeDepthBound, TheFinestAcceptedCellsStayWithinTwentyOneLevels) {
  const double extent = 2.0 * perception::kMaxAbsCoordinate;
  EXPECT_EQ(perception::OctreeDepth(extent, perception::kMinOctreeResolution), 18);
  EXPECT_EQ(perception::OctreeDepth(extent, perception::kMinVoxelResolution), 18);
  EXPECT_DOUBLE_EQ(perception::kFinestGridCell, 200.0 / 2097152.0);
  EXPECT_EQ(perception::OctreeDepth(extent, perception::kFinestGridCell), 21);
  EXPECT_EQ(perception::OctreeDepth(extent, perception::kFinestGridCell * 0.99), 22);
  EXPECT_EQ(CheckWith("change_detector.octree_resolution", 9e-5).code(),
            StatusCode::kInvalidArgument);
}

TEST(EnumValues, UnknownClassifierVariantsAreRefusedWithTheKnownValues) {
  for (const int variant : {-1, 4, 100}) {
    SCOPED_TRACE(variant);
    v1::SessionConfig config;
    config.mutable_classifier()->set_variant(static_cast<v1::ClassifierVariant>(variant));
    const Status status = CheckSessionConfig(config, "config.");
    EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
    EXPECT_THAT(std::string(status.message()),
                HasSubstr("config.classifier.variant = " + std::to_string(variant) +
                          " is not a ClassifierVariant"));
    EXPECT_THAT(std::string(status.message()), HasSubstr("3 (CLASSIFIER_VARIANT_CORRECTED_V1)"));
  }
  for (const int known : {0, 1, 2, 3}) {
    v1::SessionConfig config;
    config.mutable_classifier()->set_variant(static_cast<v1::ClassifierVariant>(known));
    EXPECT_TRUE(CheckSessionConfig(config, "config.").ok()) << known;
  }
}

TEST(EnumValues, EveryEnumOfTheConfigIsChecked) {
  v1::SessionConfig method;
  method.mutable_change_detector()->set_method(static_cast<v1::ChangeMethod>(3));
  EXPECT_THAT(std::string(CheckSessionConfig(method, "config.").message()),
              HasSubstr("config.change_detector.method = 3 is not a ChangeMethod"));
  v1::SessionConfig colour;
  colour.mutable_features()->set_colour(static_cast<v1::ColourVariant>(-5));
  EXPECT_THAT(std::string(CheckSessionConfig(colour, "state.config.").message()),
              HasSubstr("state.config.features.colour = -5"));
}

TEST(EnumValues, AnUnknownLabelIsNamedByItsPlaceInTheRequest) {
  v1::AddSamplesRequest request;
  request.add_samples()->set_label(v1::LABEL_MOVEABLE);
  request.add_samples()->set_label(static_cast<v1::Label>(7));
  const Status status = CheckEnumValues(request);
  EXPECT_EQ(status.code(), StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(status.message()),
              HasSubstr("samples[1].label = 7 is not a Label: the known values are 0 "
                        "(LABEL_UNSPECIFIED), 1 (LABEL_NOT_MOVEABLE), 2 (LABEL_MOVEABLE)"));
  v1::PostOutcomeRequest outcome;
  outcome.set_label(static_cast<v1::Label>(-1));
  EXPECT_THAT(std::string(CheckEnumValues(outcome).message()), HasSubstr("label = -1"));
  outcome.set_label(v1::LABEL_UNSPECIFIED);  // known; the handler says what is missing
  EXPECT_TRUE(CheckEnumValues(outcome).ok());
}

}  // namespace
}  // namespace relmap::service
