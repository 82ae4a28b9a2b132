// What the session store persists, as plain C++ values: a session's identity and
// configuration, its labelled samples and its latest model snapshot.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
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

inline std::int64_t UnixMilliseconds(Timestamp t) {
  return std::chrono::duration_cast<std::chrono::milliseconds>(t.time_since_epoch()).count();
}

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
  // Its last call as the latest ModelSummary recorded it, else its creation; ignored
  // by CreateSession.
  Timestamp last_used{};
};

// Every switch of Paper2018Switches in the order the store writes them: the
// sessions table's columns and the snapshot blob's bits. A new switch goes last,
// with a schema migration and a new snapshot format version.
inline constexpr bool cmm::Paper2018Switches::*kPaper2018SwitchFields[] = {
    &cmm::Paper2018Switches::pseudo_density,    &cmm::Paper2018Switches::first_sample_mean,
    &cmm::Paper2018Switches::stale_weights,     &cmm::Paper2018Switches::nearest_candidate_only,
    &cmm::Paper2018Switches::truncated_recheck, &cmm::Paper2018Switches::skip_likelihood_check,
};

// What a server records of a session's model after it learns, so that a listing
// can show a session without loading it: the components per label of the model
// learnt from the session's first `sample_count` samples, and the session's last
// call. The store keeps the record with the most samples, then the latest call.
struct ModelSummary {
  std::int64_t sample_count = 0;
  std::int64_t components[2] = {0, 0};  // per label: 0 non-moveable, 1 moveable
  Timestamp last_used{};
};

// One row of ListSessions: the session's record and what the store keeps up to
// date beside it, so that listing a session reads one row and no sample.
struct SessionSummary {
  SessionRecord record;  // its counters too
  // Samples per label, counted by AppendSample in the transaction that stores them.
  std::int64_t samples[2] = {0, 0};
  // The latest ModelSummary recorded; nullopt when none was (a session stored by a
  // server from before these summaries, and not loaded since).
  std::optional<ModelSummary> model;

  std::int64_t sample_count() const { return samples[0] + samples[1]; }
  // Whether `model` describes the model of every stored sample.
  bool model_current() const { return model.has_value() && model->sample_count == sample_count(); }
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
