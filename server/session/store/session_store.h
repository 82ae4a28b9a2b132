// The session store: durable sessions, samples and model snapshots behind one
// interface, so that the server runs on SQLite (embedded) or a shared database.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "cmm/snapshot.h"
#include "common/status.h"
#include "session/records/session_record.h"

namespace relmap::session {

// Every method is safe to call from several threads at once, returns its
// failures as a Status (never throws), and has committed its writes durably
// before it returns OK. A missing session is NOT_FOUND; stored bytes that do not
// decode are DATA_LOSS.
class SessionStore {
 public:
  virtual ~SessionStore() = default;

  // Stores a new session with zero counters. An id already stored →
  // ALREADY_EXISTS; an empty id, an invalid CMM config or a dimension < 1 →
  // INVALID_ARGUMENT.
  virtual Status CreateSession(const SessionRecord& record) = 0;
  virtual StatusOr<SessionRecord> LoadSession(std::string_view id) = 0;
  // Every session with its summary, ordered by id.
  virtual StatusOr<std::vector<SessionSummary>> ListSessions() = 0;
  // Removes the session with its samples and snapshots.
  virtual Status DeleteSession(std::string_view id) = 0;

  // Appends a sample and returns its sequence number. Idempotent on request_id:
  // a request id already stored for this session returns the original sequence
  // number and stores nothing, or FAILED_PRECONDITION if the features or label
  // differ. Features of the wrong dimension or not finite, or a label other
  // than 0/1 → INVALID_ARGUMENT.
  virtual StatusOr<std::int64_t> AppendSample(std::string_view session_id,
                                              std::string_view request_id,
                                              std::span<const double> features, int label) = 0;
  // The session's samples in sequence order, features bit for bit as appended.
  virtual StatusOr<std::vector<StoredSample>> LoadSamples(std::string_view session_id) = 0;

  // Stores `snapshot` as the session's latest, learnt from its first
  // `sample_count` samples (more than are stored → FAILED_PRECONDITION), and
  // drops older snapshots: the samples stay the record, a snapshot only saves
  // replaying them.
  virtual Status SaveSnapshot(std::string_view session_id, const cmm::CmmSnapshot& snapshot,
                              std::int64_t sample_count) = 0;
  // The latest snapshot, bit for bit as saved, or nullopt if none was saved.
  virtual StatusOr<std::optional<StoredSnapshot>> LoadLatestSnapshot(
      std::string_view session_id) = 0;

  // Adds `delta` (non-negative) to the session's counters.
  virtual Status IncrementCounters(std::string_view session_id, const SessionCounters& delta) = 0;

  // Keeps `summary` as the session's ModelSummary unless the one kept already
  // covers more samples, or as many with a later last call (a stale writer never
  // undoes a newer record). Negative
  // counts, or more samples than are stored → INVALID_ARGUMENT / FAILED_PRECONDITION.
  virtual Status RecordModelSummary(std::string_view session_id, const ModelSummary& summary) = 0;

  // Ownership, for a store that several servers share. A server writes a session
  // only while it owns it, and the store fences every write: once another server
  // has taken the session over, a write of the former owner is ABORTED and stores
  // nothing, so two servers never fork one session's history. A store with a
  // single server (the embedded SQLite file) owns everything: the defaults.
  //
  // Takes the session for this server, or renews its hold. OK with
  // `held_throughout` true when this server has owned it without interruption
  // since it last acquired it (its copy in memory is current), false when it was
  // taken now (load the session from the store). Another live server owning it →
  // UNAVAILABLE with the owner in the message and reason kSessionOwnedElsewhere
  // (metadata sessionId, owner, leaseExpiresAt); an unknown session → NOT_FOUND from a
  // shared store (the single-server default answers OK and leaves that to LoadSession).
  struct Ownership {
    bool held_throughout = true;
  };
  virtual StatusOr<Ownership> AcquireOwnership(std::string_view session_id) {
    (void)session_id;
    return Ownership{};
  }
  // Gives the session up, so that another server can take it at once (eviction,
  // deletion, a draining server). Best effort: a lost release only delays a takeover
  // until the hold expires.
  virtual void ReleaseOwnership(std::string_view session_id) { (void)session_id; }
  // Whether other servers may use the sessions too: then only the server that holds a
  // session knows when it was last used.
  virtual bool shared() const { return false; }
};

}  // namespace relmap::session
