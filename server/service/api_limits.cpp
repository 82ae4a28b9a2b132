// The table of ranges and the checks that walk a request through protobuf's reflection,
// so that a field is looked up by the name the API gives it.
#include "service/api_limits.h"

#include <fmt/format.h>
#include <google/protobuf/descriptor.h>

#include <cmath>
#include <limits>
#include <optional>

#include "perception/perception_config.h"

namespace relmap::service {
namespace {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using perception::kMaxAbsCoordinate;

constexpr double kAnyUint64 = static_cast<double>(std::numeric_limits<std::uint64_t>::max());

// [min, max] and (min, max] ranges, one line each in the table below.
constexpr FieldRange Closed(std::string_view field, double min, double max,
                            std::string_view unit = "", std::string_view setting = "") {
  return {field, min, max, false, unit, setting};
}
constexpr FieldRange OpenBelow(std::string_view field, double min, double max,
                               std::string_view unit = "", std::string_view setting = "") {
  return {field, min, max, true, unit, setting};
}

constexpr double kCoordinate = kMaxAbsCoordinate;

// Bounds beyond the layers' own checks (which ask only > 0 or >= 0 of these) keep one
// call's time and memory bounded: a VCCS importance is a relative weight (the authors'
// 0.2, 0.4, 0.4), a count of neighbours, iterations or points a small number, a radius or
// distance of the change detector smaller than the table-top scenes it labels. The
// change detector's settings are `change.*` in perception::ChangeDetectorConfig.
// clang-format off
constexpr FieldRange kSessionConfigRanges[] = {
    Closed("classifier.alpha", 0, 1),
    // λ beyond 1e6 is not a regularisation of any feature scale, only an overflow.
    OpenBelow("classifier.regularization", 0, 1e6),
    Closed("supervoxels.voxel_resolution", perception::kMinVoxelResolution,
           perception::kMaxVoxelResolution, "m"),
    Closed("supervoxels.seed_resolution", perception::kMinVoxelResolution,
           perception::kMaxSeedResolution, "m"),
    Closed("supervoxels.colour_importance", 0, 100),
    Closed("supervoxels.spatial_importance", 0, 100),
    Closed("supervoxels.normal_importance", 0, 100),
    Closed("supervoxels.min_voxels", 1, 100000),
    // Beyond the coordinates a cloud may have (DecodeLimits::max_abs_coordinate), a bound
    // crops nothing.
    Closed("workspace.min_x", -kCoordinate, kCoordinate, "m"),
    Closed("workspace.max_x", -kCoordinate, kCoordinate, "m"),
    Closed("workspace.min_y", -kCoordinate, kCoordinate, "m"),
    Closed("workspace.max_y", -kCoordinate, kCoordinate, "m"),
    Closed("workspace.min_z", -kCoordinate, kCoordinate, "m"),
    Closed("workspace.max_z", -kCoordinate, kCoordinate, "m"),
    Closed("seed", 0, kAnyUint64),
    // 0 (unset) means 48; session::Validate says "feature dimension".
    Closed("feature_dimension", 1, 4096, "", "feature dimension"),
    // 1 mm cells keep the octree over ±100 m at 18 levels (perception::kFinestGridCell).
    Closed("change_detector.octree_resolution", perception::kMinOctreeResolution,
           perception::kMaxOctreeResolution, "m", "change.octree_resolution"),
    Closed("change_detector.depth_noise", 0, 1, "1/m", "change.depth_noise"),
    Closed("change_detector.sor_mean_k", 1, 1000, "", "change.sor_mean_k"),
    Closed("change_detector.sor_stddev_mul", 0, 100, "", "change.sor_stddev_mul"),
    OpenBelow("change_detector.ror_radius", 0, 0.5, "m", "change.ror_radius"),
    Closed("change_detector.ror_min_neighbours", 0, 10000, "", "change.ror_min_neighbours"),
    Closed("change_detector.icp_max_iterations", 1, 1000, "", "change.icp_max_iterations"),
    OpenBelow("change_detector.icp_max_correspondence", 0, 1, "m",
              "change.icp_max_correspondence"),
    OpenBelow("change_detector.max_fitness", 0, 1, "m²", "change.max_fitness"),
    Closed("change_detector.noise_sigma_base", 0, 1, "m", "change.noise.sigma_base"),
    Closed("change_detector.noise_sigma_quadratic", 0, 1, "1/m", "change.noise.sigma_quadratic"),
    Closed("change_detector.noise_reference_depth", 0, 10, "m", "change.noise.reference_depth"),
    Closed("change_detector.noise_quantisation", 0, 1, "1/m", "change.noise.quantisation"),
    OpenBelow("change_detector.tolerance_sigmas", 0, 10, "", "change.tolerance_sigmas"),
    Closed("change_detector.search_window", 0, 8, "pixels", "change.search_window"),
    OpenBelow("change_detector.min_vacated_fraction", 0, 1, "", "change.min_vacated_fraction"),
    Closed("change_detector.min_vacated_points", 1, 100000, "", "change.min_vacated_points"),
    Closed("change_detector.colour_tolerance", 0, 255, "", "change.colour_tolerance"),
    Closed("change_detector.object_smooth_angle_deg", 0, 90, "degrees",
           "change.object_smooth_angle_deg"),
    Closed("change_detector.min_motion", 0, perception::kMaxMinMotion, "m", "change.min_motion"),
    Closed("features.fpfh_radius", perception::kMinFpfhRadius, perception::kMaxFpfhRadius, "m"),
    Closed("exploration.random_share", 0, 1),
};
// clang-format on

// The value of a numeric field as a double; nullopt for the other types.
std::optional<double> NumberOf(const Message& message, const FieldDescriptor& field) {
  const auto& reflection = *message.GetReflection();
  switch (field.cpp_type()) {
    case FieldDescriptor::CPPTYPE_INT32:
      return reflection.GetInt32(message, &field);
    case FieldDescriptor::CPPTYPE_INT64:
      return static_cast<double>(reflection.GetInt64(message, &field));
    case FieldDescriptor::CPPTYPE_UINT32:
      return reflection.GetUInt32(message, &field);
    case FieldDescriptor::CPPTYPE_UINT64:
      return static_cast<double>(reflection.GetUInt64(message, &field));
    case FieldDescriptor::CPPTYPE_FLOAT:
      return reflection.GetFloat(message, &field);
    case FieldDescriptor::CPPTYPE_DOUBLE:
      return reflection.GetDouble(message, &field);
    default:
      return std::nullopt;
  }
}

// The value of the field at `path` ("a.b.c") in `message`, or nullopt when it or a
// message on the way is not set (the default applies).
std::optional<double> SetValueAt(const Message& message, std::string_view path) {
  const Message* at = &message;
  while (true) {
    const std::size_t dot = path.find('.');
    const FieldDescriptor* field =
        at->GetDescriptor()->FindFieldByName(std::string(path.substr(0, dot)));
    if (field == nullptr || field->is_repeated() || !at->GetReflection()->HasField(*at, field)) {
      return std::nullopt;
    }
    if (dot == std::string_view::npos) return NumberOf(*at, *field);
    if (field->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE) return std::nullopt;
    at = &at->GetReflection()->GetMessage(*at, field);
    path.remove_prefix(dot + 1);
  }
}

// Whole numbers as integers, a float field's value (or a float constant) as the float it
// is ("0.001", not 0.0010000000474974513), anything else as the shortest double.
std::string Number(double value) {
  if (value == std::trunc(value) && std::abs(value) < 1e15) {
    return std::to_string(static_cast<long long>(value));
  }
  if (std::abs(value) <= std::numeric_limits<float>::max() &&
      static_cast<double>(static_cast<float>(value)) == value) {
    return fmt::format("{}", static_cast<float>(value));
  }
  return fmt::format("{}", value);
}

std::string RangeText(const FieldRange& range) {
  std::string text =
      fmt::format("{}{}, {}]", range.min_open ? "(" : "[", Number(range.min), Number(range.max));
  if (!range.unit.empty()) text += " " + std::string(range.unit);
  return text;
}

std::string KnownValues(const google::protobuf::EnumDescriptor& type) {
  std::string known;
  for (int i = 0; i < type.value_count(); ++i) {
    const auto& value = *type.value(i);
    known += fmt::format("{}{} ({})", i == 0 ? "" : ", ", value.number(), value.name());
  }
  return known;
}

Status CheckEnum(const FieldDescriptor& field, int value, const std::string& path) {
  if (field.enum_type()->FindValueByNumber(value) != nullptr) return OkStatus();
  return InvalidArgumentError(fmt::format("{} = {} is not a {}: the known values are {}", path,
                                          value, field.enum_type()->name(),
                                          KnownValues(*field.enum_type())));
}

Status CheckEnumsAt(const Message& message, const std::string& prefix) {
  const auto& descriptor = *message.GetDescriptor();
  const auto& reflection = *message.GetReflection();
  for (int f = 0; f < descriptor.field_count(); ++f) {
    const FieldDescriptor& field = *descriptor.field(f);
    const std::string path = prefix + field.name();
    if (field.cpp_type() == FieldDescriptor::CPPTYPE_ENUM) {
      if (!field.is_repeated()) {
        if (Status s = CheckEnum(field, reflection.GetEnumValue(message, &field), path); !s.ok()) {
          return s;
        }
        continue;
      }
      for (int i = 0; i < reflection.FieldSize(message, &field); ++i) {
        const int value = reflection.GetRepeatedEnumValue(message, &field, i);
        if (Status s = CheckEnum(field, value, fmt::format("{}[{}]", path, i)); !s.ok()) return s;
      }
    } else if (field.cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE) {
      if (!field.is_repeated()) {
        if (!reflection.HasField(message, &field)) continue;
        if (Status s = CheckEnumsAt(reflection.GetMessage(message, &field), path + "."); !s.ok()) {
          return s;
        }
        continue;
      }
      for (int i = 0; i < reflection.FieldSize(message, &field); ++i) {
        const Message& element = reflection.GetRepeatedMessage(message, &field, i);
        if (Status s = CheckEnumsAt(element, fmt::format("{}[{}].", path, i)); !s.ok()) return s;
      }
    }
  }
  return OkStatus();
}

}  // namespace

Status CheckRange(const FieldRange& range, std::string_view path, double value) {
  const bool above_min = range.min_open ? value > range.min : value >= range.min;
  if (above_min && value <= range.max) return OkStatus();  // false for NaN
  const std::string name =
      range.setting.empty() ? std::string(path) : fmt::format("{}: {}", path, range.setting);
  return InvalidArgumentError(
      fmt::format("{} must lie in {}, got {}", name, RangeText(range), Number(value)));
}

std::span<const FieldRange> SessionConfigRanges() { return kSessionConfigRanges; }

const FieldRange* SessionConfigRange(std::string_view field) {
  for (const FieldRange& range : kSessionConfigRanges) {
    if (range.field == field) return &range;
  }
  return nullptr;
}

Status CheckSessionConfig(const v1::SessionConfig& config, std::string_view prefix) {
  if (Status s = CheckEnumsAt(config, std::string(prefix)); !s.ok()) return s;
  for (const FieldRange& range : kSessionConfigRanges) {
    const std::optional<double> value = SetValueAt(config, range.field);
    if (!value) continue;
    if (Status s = CheckRange(range, std::string(prefix) + std::string(range.field), *value);
        !s.ok()) {
      return s;
    }
  }
  return OkStatus();
}

Status CheckEnumValues(const Message& message) { return CheckEnumsAt(message, ""); }

}  // namespace relmap::service
