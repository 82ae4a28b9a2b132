// The documented range of every numeric field of SessionConfig, and the check that every
// enum field of a request holds a known value: what a handler checks before any work.
// The proto's comments state the same ranges (the API's reference). The other numeric
// fields of the requests are bounded by the server's limits (points, feature vectors per
// request: RESOURCE_EXHAUSTED) or by the session's state (frame and supervoxel ids), and
// ListSessions' page size by session/registry/session_listing.h.
#pragma once

#include <google/protobuf/message.h>

#include <span>
#include <string>
#include <string_view>

#include "common/status.h"
#include "relmap/v1/relevance_service.pb.h"

namespace relmap::service {

// The range of one numeric field.
struct FieldRange {
  // The API's name of the field, relative to the message of its table
  // ("supervoxels.voxel_resolution" in SessionConfig).
  std::string_view field;
  double min = 0.0;
  double max = 0.0;
  // (min, max] instead of [min, max].
  bool min_open = false;
  std::string_view unit;
  // The layer config's name of the setting where it is not the API's
  // ("change.octree_resolution"), as the tools and the layers' own checks say it.
  std::string_view setting;
};

// OK when `value` (finite) lies in `range`; otherwise INVALID_ARGUMENT naming `path` (the
// field as the request spells it), the range and the value.
Status CheckRange(const FieldRange& range, std::string_view path, double value);

// The ranges of SessionConfig's numeric fields, one entry per field, by API name. A
// field a request leaves unset takes its default, which is in range.
std::span<const FieldRange> SessionConfigRanges();

// The range of a SessionConfig field by API name, or nullptr.
const FieldRange* SessionConfigRange(std::string_view field);

// Every numeric field that `config` sets lies in its range (SessionConfigRanges), and every
// enum field holds one of its enum's values; the message names the field as
// `prefix` + its API name ("config." in CreateSession). Cross-field conditions (seed
// spacing at least the voxel size, a workspace box with min < max) are the layers' own
// checks (session::Validate), which follow.
Status CheckSessionConfig(const v1::SessionConfig& config, std::string_view prefix);

// Every enum field of `message` and of the messages in it holds a value its enum names
// (proto3 enums are open: a client may send any number); INVALID_ARGUMENT names the field
// ("samples[3].label") and the known values.
Status CheckEnumValues(const google::protobuf::Message& message);

}  // namespace relmap::service
