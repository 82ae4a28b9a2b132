// What the session store persists, as plain C++ values: a session's identity and
// configuration, its labelled samples and its latest model snapshot.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "cmm/config.h"
#include "cmm/snapshot.h"

namespace relmap::session {

// Microseconds since the Unix epoch: what the store keeps, so a record reads back
// exactly as it was written.
using Timestamp = std::chrono::sys_time<std::chrono::microseconds>;

// Running totals of a session; the store only adds to them.
struct SessionCounters {
  std::int64_t frames_computed = 0;
  std::int64_t interactions = 0;
};

struct SessionRecord {
  std::string id;
  // The server keeps a SHA-256 hex digest of the session token, never the token.
  std::string token_hash;
  Timestamp created_at{};
  // The session's configuration as the server serialised it; opaque to the store.
  std::string config;
  // What rebuilding the model needs; stored field by field, not as a blob, so
  // that the database can be queried and migrated.
  cmm::CmmConfig cmm_config;
  int feature_dimension = 0;
  SessionCounters counters;  // ignored by CreateSession: a new session starts at zero
};

// Every switch of Paper2018Switches in the order the store writes them: the
// sessions table's columns and the snapshot blob's bits. A new switch goes last,
// with a schema migration and a new snapshot format version.
inline constexpr bool cmm::Paper2018Switches::*kPaper2018SwitchFields[] = {
    &cmm::Paper2018Switches::pseudo_density,    &cmm::Paper2018Switches::first_sample_mean,
    &cmm::Paper2018Switches::stale_weights,     &cmm::Paper2018Switches::nearest_candidate_only,
    &cmm::Paper2018Switches::truncated_recheck, &cmm::Paper2018Switches::skip_likelihood_check,
};

// One row of ListSessions.
struct SessionSummary {
  std::string id;
  Timestamp created_at{};
  std::int64_t sample_count = 0;
};

// A labelled sample as appended. Sequence numbers of a session count from 0 in
// append order, without gaps.
struct StoredSample {
  std::int64_t sequence = 0;
  std::string request_id;
  std::vector<double> features;
  int label = 0;
};

// A model snapshot and how many of the session's samples (the first
// `sample_count` in sequence order) it has learnt from; the server replays the
// rest after restoring it.
struct StoredSnapshot {
  cmm::CmmSnapshot snapshot;
  std::int64_t sample_count = 0;
};

}  // namespace relmap::session
