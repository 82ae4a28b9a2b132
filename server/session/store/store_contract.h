// What every SessionStore implementation checks and says the same way: the
// validation of its arguments, the stored form of sample features and the
// messages of its errors, apart from any SQL.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cmm/snapshot.h"
#include "common/status.h"
#include "session/records/session_record.h"

namespace relmap::session {

// "\"id\"", for messages.
std::string Quoted(std::string_view id);

// NOT_FOUND naming the session.
Status SessionNotFound(std::string_view id);

// CreateSession's argument checks: an id, a positive dimension, a valid CMM config.
Status CheckRecord(const SessionRecord& record);

// AppendSample's checks that need no stored state: a request id, a 0/1 label,
// finite features.
Status CheckSample(std::string_view request_id, std::span<const double> features, int label);
// The features' count against the session's dimension.
Status CheckFeatureCount(std::string_view session_id, std::span<const double> features,
                         int dimension);
// FAILED_PRECONDITION for a request id stored with other features or label.
Status RequestIdReused(std::string_view session_id, std::string_view request_id);

// SaveSnapshot's checks: a non-negative count before anything is read, then the
// snapshot's dimension and count against the session's.
Status CheckSnapshotSampleCount(std::int64_t sample_count);
Status CheckSnapshotAgainstSession(std::string_view session_id, const cmm::CmmSnapshot& snapshot,
                                   std::int64_t sample_count, int dimension,
                                   std::int64_t stored_samples);
// The DATA_LOSS or other failure of decoding a stored snapshot, naming the session.
Status SnapshotDecodeError(std::string_view session_id, const Status& status);

// IncrementCounters' check: counters only grow.
Status CheckCounterDelta(const SessionCounters& delta);

// RecordModelSummary's checks: counts from 0, then no more samples than are stored.
Status CheckModelSummary(const ModelSummary& summary);
Status CheckModelSummaryAgainstSession(std::string_view session_id, const ModelSummary& summary,
                                       std::int64_t stored_samples);

// Little-endian IEEE doubles, 8 bytes each: exact, and independent of the host.
std::string EncodeFeatures(std::span<const double> features);
// The features of sample `sequence`, or DATA_LOSS if the blob does not hold
// `dimension` doubles.
StatusOr<std::vector<double>> DecodeFeatures(std::string_view blob, int dimension,
                                             std::string_view session_id, std::int64_t sequence);

}  // namespace relmap::session
