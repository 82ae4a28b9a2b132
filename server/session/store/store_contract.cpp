// The SQL-independent half of the SessionStore contract, shared by the stores.
#include "session/store/store_contract.h"

#include <cmath>

#include "cmm/config.h"
#include "session/records/little_endian.h"

namespace relmap::session {

// Built by append: GCC 12 warns (-Wrestrict, falsely) on "\"" + std::string.
std::string Quoted(std::string_view id) { return std::string("\"").append(id).append("\""); }

Status SessionNotFound(std::string_view id) {
  return NotFoundError("session " + Quoted(id) + " not found");
}

Status CheckRecord(const SessionRecord& r) {
  if (r.id.empty()) return InvalidArgumentError("empty session id");
  if (r.feature_dimension < 1) {
    return InvalidArgumentError("feature dimension " + std::to_string(r.feature_dimension) +
                                " is not positive");
  }
  if (Status status = cmm::Validate(r.cmm_config); !status.ok()) {
    return InvalidArgumentError("session " + Quoted(r.id) + ": " + status.message());
  }
  return OkStatus();
}

Status CheckSample(std::string_view request_id, std::span<const double> features, int label) {
  if (request_id.empty()) return InvalidArgumentError("empty request id");
  if (label != 0 && label != 1) {
    return InvalidArgumentError("label " + std::to_string(label) + " is neither 0 nor 1");
  }
  for (std::size_t k = 0; k < features.size(); ++k) {
    // The model refuses non-finite features; storing one would make every
    // replay of the session fail.
    if (!std::isfinite(features[k])) {
      return InvalidArgumentError("feature " + std::to_string(k) + " is not finite");
    }
  }
  return OkStatus();
}

Status CheckFeatureCount(std::string_view session_id, std::span<const double> features,
                         int dimension) {
  if (features.size() == static_cast<std::size_t>(dimension)) return OkStatus();
  return InvalidArgumentError("session " + Quoted(session_id) + " takes " +
                              std::to_string(dimension) + " features, not " +
                              std::to_string(features.size()));
}

Status RequestIdReused(std::string_view session_id, std::string_view request_id) {
  return FailedPreconditionError("request id " + Quoted(request_id) +
                                 " reused with different content in session " + Quoted(session_id));
}

Status CheckSnapshotSampleCount(std::int64_t sample_count) {
  if (sample_count >= 0) return OkStatus();
  return InvalidArgumentError("negative snapshot sample count " + std::to_string(sample_count));
}

Status CheckSnapshotAgainstSession(std::string_view session_id, const cmm::CmmSnapshot& snapshot,
                                   std::int64_t sample_count, int dimension,
                                   std::int64_t stored_samples) {
  if (snapshot.dimension != dimension) {
    return InvalidArgumentError("snapshot of dimension " + std::to_string(snapshot.dimension) +
                                " for session " + Quoted(session_id) + " of dimension " +
                                std::to_string(dimension));
  }
  if (sample_count > stored_samples) {
    return FailedPreconditionError("snapshot claims " + std::to_string(sample_count) +
                                   " samples; session " + Quoted(session_id) + " stores " +
                                   std::to_string(stored_samples));
  }
  return OkStatus();
}

Status SnapshotDecodeError(std::string_view session_id, const Status& status) {
  return Status(status.code(),
                "snapshot of session " + Quoted(session_id) + ": " + status.message());
}

Status CheckCounterDelta(const SessionCounters& delta) {
  if (delta.frames_computed >= 0 && delta.interactions >= 0) return OkStatus();
  return InvalidArgumentError("counters only grow; got a negative increment");
}

Status CheckModelSummary(const ModelSummary& summary) {
  if (summary.sample_count >= 0 && summary.components[0] >= 0 && summary.components[1] >= 0) {
    return OkStatus();
  }
  return InvalidArgumentError("a model summary counts samples and components from 0");
}

Status CheckModelSummaryAgainstSession(std::string_view session_id, const ModelSummary& summary,
                                       std::int64_t stored_samples) {
  if (summary.sample_count <= stored_samples) return OkStatus();
  return FailedPreconditionError("model summary claims " + std::to_string(summary.sample_count) +
                                 " samples; session " + Quoted(session_id) + " stores " +
                                 std::to_string(stored_samples));
}

std::string EncodeFeatures(std::span<const double> features) {
  std::string blob;
  blob.reserve(features.size() * 8);
  LittleEndianWriter(blob).F64s(features);
  return blob;
}

StatusOr<std::vector<double>> DecodeFeatures(std::string_view blob, int dimension,
                                             std::string_view session_id, std::int64_t sequence) {
  if (blob.size() != static_cast<std::size_t>(dimension) * 8) {
    return DataLossError("sample " + std::to_string(sequence) + " of session " +
                         Quoted(session_id) + " has a " + std::to_string(blob.size()) +
                         "-byte feature blob; dimension " + std::to_string(dimension) + " needs " +
                         std::to_string(dimension * 8));
  }
  std::vector<double> features(static_cast<std::size_t>(dimension));
  LittleEndianReader(blob).F64s(features);
  return features;
}

}  // namespace relmap::session
